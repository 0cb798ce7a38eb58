#pragma once
// EmptySpace: the macro cells (macro_cells.hpp) classified against a transfer
// function, and the walk that lets a ray leap over the empty ones (the 3D DDA
// of Amanatides & Woo 1987 over macro cells).
//
// A macro cell is empty when its range [min - d, max + d] contributes nothing
// (ZeroOpacity::over), d = 1e-5 (max - min + max |value| of the volume): the
// margin covers the rounding of a sample position that lies on a face between
// an empty and a non-empty macro cell, and preint1's float interpolation and
// table index (float_sampler.hpp, float_lookup.hpp: a few float roundings of
// the largest |value|). Exactness for the integrators:
// - riemann: a sample in an empty cell has tau = 0 and adds nothing;
// - preint1: along a run of empty cells each neighbour shares a face (and the
//   samples on it) with the next, so their ranges overlap and their union is
//   one interval with zero opacity; a slab between two samples in the run reads
//   table entries inside it, which are zero;
// - preint2: the same with slabs of three samples, when the cells were
//   classified with TableOrder::Second (zero_opacity.hpp): the union of the
//   run's ranges then lies far enough inside one run of zero table scalars
//   that the parabola through any three of its scalars stays in that run.
// Classifying is O(macro cells) and takes milliseconds (bench_macro_cells).
// A walk covers only the box of the non-empty macro cells: everything a ray
// meets before or after it is empty, however many macro cells that is (most
// of a walk's steps in a volume whose data sits inside air or background).
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "vri/geometry.hpp"
#include "tables/zero_opacity.hpp"
#include "volume/macro_cells.hpp"

namespace vri {

// How far an interpolated scalar of `volume` may round beyond its corners'
// range: ranges are widened by it before they are classified (1e-5 of the
// volume's range plus its largest magnitude).
double interpolation_margin(const GridVolume& volume);

class EmptySpace {
 public:
  EmptySpace(const MacroCells& cells, const ZeroOpacity& zero);

  const MacroCells& cells() const { return cells_; }
  bool empty(std::size_t index) const { return empty_[index] != 0; }
  std::size_t empty_count() const;
  // The box of the non-empty macro cells in world space, within the
  // volume's: a ray that misses it crosses only empty macro cells (a point
  // at the volume's origin where every cell is empty).
  Box occupied_box() const;
  // Boxes that hold every non-empty macro cell, within occupied_box(): runs
  // of them along x, over blocks of 2^k macro cells a side where there are
  // more than 4096 macro cells (the renderer projects each box per frame).
  std::vector<Box> occupied_parts() const;

  // A run of empty (or of non-empty) macro cells along a ray, which ends at
  // t_end, where the ray enters a cell of the other kind, or at t_max.
  struct Run {
    bool empty;
    double t_end;
  };

  // One walk of the macro cells along a ray from the cell at t (the one
  // GridVolume::sample reads there), run after run: each run starts exactly
  // where the last one ended, so a walk never stalls on a face that
  // rounding puts on the wrong side, and finds the ray's first cell and the
  // box once.
  class Walk {
   public:
    Walk(const EmptySpace& space, const Ray& ray, double t, double t_max);
    // The run from the current cell on; false once t_max was reached.
    bool next(Run& run);

   private:
    double exit(int a, int cell) const;  // where the ray leaves macro cell `cell` of axis a through its far face
    const EmptySpace& space_;
    const Ray& ray_;
    double t_max_, limit_ = 0;  // the walk's end: t_max or, before it, where the ray leaves the box
    double box_entry_ = -std::numeric_limits<double>::infinity();  // an empty run before the box, to here
    std::array<int, 3> cell_{};
    std::size_t index_ = 0;  // cell_'s (MacroCells::index)
    int step_[3];
    double inverse_[3];  // 1 / the ray's direction (0 where it is 0): a product per face, not a division
    double leave_[3] = {};
    bool tail_ = false;  // what is left is one empty run to t_max
    bool done_ = false;
  };

 private:
  // Where the ray lies in the box of the non-empty macro cells: [b0, b1],
  // with the faces' planes crossed at face(axis, plane) (the walk's
  // formula); false when it misses the box or there is none.
  template <class Face>
  bool occupied_span(const Ray& ray, Face&& face, double& b0, double& b1) const;
  // The world coordinate of macro-cell face `cell` on `axis`.
  double macro_face(int axis, int cell) const;

  const MacroCells& cells_;
  std::vector<std::uint8_t> empty_;
  // The box of the non-empty macro cells: macro cells [lo, hi) on each axis
  // (lo = dims, hi = 0 when there is none).
  std::array<int, 3> box_lo_, box_hi_;
  bool whole_ = false;  // the box is the whole grid: it bounds no walk
};

// Calls visit(Interval part) for each run of non-empty macro cells along
// [iv.t0, iv.t1] (part: iv with t0 and t1 those of the run), front to back,
// until visit returns false; with no `space`, once for the whole of iv. The
// runs and the leaps between them partition iv: an integrator that walks the
// parts adds what it would add walking iv wherever the empty runs add
// nothing. Runs of no length (two faces crossed at once) are not visited.
template <class Visit>
void for_each_occupied_run(const EmptySpace* space, const Ray& ray, const Interval& iv, Visit&& visit) {
  if (!space) {
    visit(iv);
    return;
  }
  EmptySpace::Walk walk(*space, ray, iv.t0, iv.t1);
  EmptySpace::Run run;
  for (double t = iv.t0; t < iv.t1 && walk.next(run); t = run.t_end) {
    if (run.empty || !(run.t_end > t)) continue;
    Interval part = iv;
    part.t0 = t;
    part.t1 = run.t_end;
    if (!visit(part)) return;
  }
}

}  // namespace vri
