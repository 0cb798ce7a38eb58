#pragma once
// The cell-segment march of preint2-dual (preint2_dual.hpp), shared by its
// double path and its float path: which segments empty-space skipping leaves
// out, and the float path itself.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

#include "ray_steps.hpp"
#include "vri/core/ray.hpp"
#include "vri/tables/second_order_float_lookup.hpp"
#include "vri/volume/cell_traversal.hpp"
#include "vri/volume/empty_space.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri::detail {

// Segments in a run of empty macro cells (classified for second-order
// entries): their three samples are in the run, so their entries are zero,
// and the march need not sample them. Queries the macro-cell walk only once
// t passes the end of the last run found.
class SegmentSkip {
 public:
  SegmentSkip(const Leap& leap, const Ray& ray, double t_max) : leap_(leap), ray_(ray), t_max_(t_max) {}
  bool skipped(const CellSegment& seg) {
    if (!leap_.space) return false;
    if (seg.ta >= t_check_) {
      const EmptySpace::Run run = leap_.space->run(ray_, seg.ta, t_max_);
      t_check_ = run.t_end;
      empty_until_ = run.empty ? run.t_end : -kInf;
    }
    return seg.tb <= empty_until_;
  }

 private:
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  const Leap& leap_;
  const Ray& ray_;
  double t_max_, empty_until_ = -kInf, t_check_ = -kInf;
};

// The (l, s_f, s_m, s_b) table in float: each length slice read as preint2's
// float lookup reads its table (trilinear, 4-float vectors), the two slices
// next to l blended linearly.
class DualFloatLookup {
 public:
  explicit DualFloatLookup(const SecondOrderLengthTable& table) : max_length_(table.max_length()) {
    for (const SecondOrderTable& t : table.slices()) slices_.emplace_back(t);
  }
  Float4 lookup(double length, float s_f, float s_m, float s_b) const {
    const int m = static_cast<int>(slices_.size());
    const double u = std::clamp(length / max_length_, 0.0, 1.0) * (m - 1);
    const int i = std::min(static_cast<int>(u), m - 2);
    const float w = static_cast<float>(u - i);
    const std::array<FloatAxis::Place, 3> p = {slices_[i].place(s_f), slices_[i].place(s_m), slices_[i].place(s_b)};
    const Float4 lo = slices_[i].blend(slices_[i].find(p)), hi = slices_[i + 1].blend(slices_[i + 1].find(p));
    return lo + w * (hi - lo);
  }

 private:
  std::vector<SecondOrderFloatLookup> slices_;
  double max_length_;
};

// The float path (unlit): per segment the cell's eight values are read once
// and its three samples evaluated from them in float (the front in its own
// cell too, not carried over from the previous one, so that skipping a
// segment changes no byte); lookups and compositing in float. The traversal
// stays in double, so the segments are the double path's.
template <class Value>
Rgba march_cells_float(const GridVolume& volume, const Value* values, const DualFloatLookup& table, const Ray& ray,
                       const Leap& leap) {
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const std::size_t sy = volume.dims()[0], sz = sy * volume.dims()[1];
  SegmentSkip skip(leap, ray, iv->t1);
  float T = 1, C[3] = {0, 0, 0};
  for_each_cell_segment(volume, ray, *iv, [&](const CellSegment& seg) {
    if (T < leap.termination) return false;
    if (skip.skipped(seg)) return true;
    const Value* v = values + seg.cell[0] + sy * seg.cell[1] + sz * seg.cell[2];
    const float c[8] = {float(v[0]),      float(v[1]),          float(v[sy]),      float(v[sy + 1]),
                        float(v[sz]),     float(v[sz + 1]),     float(v[sz + sy]), float(v[sz + sy + 1])};
    const auto at = [&](double dt) {
      float u[3];
      for (int a = 0; a < 3; ++a) u[a] = std::clamp(static_cast<float>(seg.local0[a] + dt * seg.local_dir[a]), 0.0f, 1.0f);
      const float x0 = c[0] + u[0] * (c[1] - c[0]), x1 = c[2] + u[0] * (c[3] - c[2]);
      const float x2 = c[4] + u[0] * (c[5] - c[4]), x3 = c[6] + u[0] * (c[7] - c[6]);
      const float y0 = x0 + u[1] * (x1 - x0), y1 = x2 + u[1] * (x3 - x2);
      return y0 + u[2] * (y1 - y0);
    };
    const double length = seg.tb - seg.ta;
    const float front = at(0), middle = at(0.5 * length), back = at(length);
    const Float4 e = table.lookup(length, front, middle, back);
    for (int k = 0; k < 3; ++k) C[k] += T * e[k];
    T *= 1 - e[3];
    return true;
  });
  return {C[0], C[1], C[2], 1 - T};
}

}  // namespace vri::detail
