#pragma once
// The cell-segment march of preint2-dual (preint2_dual.hpp), shared by its
// double path and its float path: which segments empty-space skipping leaves
// out, and the float path itself (unlit and lit in both modes).
#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include "methods/preint/float_march.hpp"
#include "methods/march/float_shading.hpp"
#include "methods/march/ray_steps.hpp"
#include "vri/geometry.hpp"
#include "tables/second_order_float_lookup.hpp"
#include "tables/slab_table.hpp"
#include "tables/zero_spots.hpp"
#include "volume/cell_traversal.hpp"
#include "volume/empty_space.hpp"
#include "vri/volume.hpp"

namespace vri::detail {

// Segments in a run of empty macro cells (classified for second-order
// entries): their three samples are in the run, so their entries are zero,
// and the march need not sample them. The runs are the ray's one walk
// (MacroRuns), asked for the next only once t passes the end of the last.
class SegmentSkip {
 public:
  SegmentSkip(const Leap& leap, const Ray& ray, double t_max) : runs_(leap.space, ray, t_max) {}
  bool skipped(const CellSegment& seg) { return skipped(seg.ta, seg.tb); }
  bool skipped(double ta, double tb) {
    if (!runs_.skipping()) return false;
    if (ta >= runs_.end()) {
      // The run that holds ta (a leap lands on the end of the run it crossed).
      const EmptySpace::Run run = runs_.at(ta);
      empty_until_ = run.empty ? run.t_end : -std::numeric_limits<double>::infinity();
    }
    return tb <= empty_until_;
  }
  // The end of the last run found, if empty (else -inf): every segment that
  // ends by it is skipped.
  double empty_until() const { return empty_until_; }

 private:
  MacroRuns runs_;
  double empty_until_ = -std::numeric_limits<double>::infinity();
};

// The (l, s_f, s_m, s_b) table in float: the two length slices next to l and,
// in each, the eight entries around (s_f, s_m, s_b) on preint2's float axis
// (SecondOrderFloatLookup's layout: rows of entries along s_b, 4 floats
// each). The blend takes the slices first, entry by entry, then s_m, s_f
// and s_b last: in that order the two entries of a row (b, b + 1) stay
// side by side as one 8-float vector until the end, which is how the
// packets (float_packet_dual.cpp) blend each lane, with the same operations.
// With interpolated lighting the weighted tables (middle, back) are read at
// the same spot. A spot whose entries are all zero in both slices of every
// table (ZeroSpots) is not read: its blend is +0, as reading would give.
class DualFloatLookup {
 public:
  explicit DualFloatLookup(const SecondOrderLengthTable& full, const SecondOrderLengthTable* middle = nullptr,
                           const SecondOrderLengthTable* back = nullptr)
      : max_length_(full.max_length()) {
    for (std::size_t i = 0; i < full.slices().size(); ++i) {
      slices_.emplace_back(full.slices()[i]);
      weighted_.push_back({middle ? middle->slices()[i].data() : nullptr, back ? back->slices()[i].data() : nullptr});
    }
    // Every slice is built on the one discrete transfer function: one axis
    // and one layout, on which a spot is found once for both slices.
    for (const SecondOrderFloatLookup& slice : slices_)
      if (slice.axis().lo() != slices_[0].axis().lo() || slice.axis().scale() != slices_[0].axis().scale() ||
          slice.size() != slices_[0].size())
        throw std::logic_error("DualFloatLookup: slices on different scalar axes");
    std::vector<const float*> tables;
    for (int i = 0; i < lengths(); ++i)
      for (int k = 0; k < 3; ++k)
        if (data(i, k)) tables.push_back(data(i, k));
    zero_spots_.emplace(slices_[0].size(), tables);
  }
  struct Spot {
    int i;            // slices i and i + 1
    float wl;         // slice i + 1's weight
    std::size_t at;   // entry (f, m, b), in floats from a slice's start
    float wf, wm, wb;
  };
  // Finding a spot starts loading its entries (four rows in each slice).
  Spot find(double length, float s_f, float s_m, float s_b) const {
    const LengthBracket l = length_bracket(length, max_length_, static_cast<int>(slices_.size()));
    const SecondOrderFloatLookup& axes = slices_[0];
    const FloatAxis::Place f = axes.place(s_f), m = axes.place(s_m), b = axes.place(s_b);
    const std::size_t at = axes.offset(f.i, m.i, b.i);
    if (!zero(at)) {
      slices_[l.i].prefetch(at);
      slices_[l.i + 1].prefetch(at);
    }
    return {l.i, static_cast<float>(l.w), at, f.w, m.w, b.w};
  }
  // Table k (0 the unweighted one, 1 middle, 2 back) at the spot.
  Float4 blend(const Spot& spot, int k = 0) const {
    if (zero(spot.at)) return Float4{0, 0, 0, 0};
    const float *lo = data(spot.i, k) + spot.at, *hi = data(spot.i + 1, k) + spot.at;
    const auto lerp = [](Float4 a, Float4 b, float w) { return a + w * (b - a); };
    Float4 r[2][2][2];  // [f][m][b]: the rows' entries, slices blended
    for (int f = 0; f < 2; ++f)
      for (int m = 0; m < 2; ++m)
        for (int b = 0; b < 2; ++b) {
          const std::size_t add = f * plane() + m * row() + 4 * b;
          r[f][m][b] = lerp(load_float4(lo + add), load_float4(hi + add), spot.wl);
        }
    Float4 e[2];  // entries b and b + 1, blended along s_m, then s_f
    for (int b = 0; b < 2; ++b)
      e[b] = lerp(lerp(r[0][0][b], r[0][1][b], spot.wm), lerp(r[1][0][b], r[1][1][b], spot.wm), spot.wf);
    return lerp(e[0], e[1], spot.wb);
  }

  // What `find` reads, for the ray packets (float_packet_dual.cpp).
  int lengths() const { return static_cast<int>(slices_.size()); }
  const SecondOrderFloatLookup& slice(int i) const { return slices_[i]; }
  // Slice i of table k (0 the unweighted one, 1 middle, 2 back), all in slice i's layout.
  const float* data(int i, int k) const { return k == 0 ? slices_[i].data() : weighted_[i][k - 1]; }
  double max_length() const { return max_length_; }
  // Whether the spot at entry `at` (floats from a slice's start) reads only zeros.
  bool zero(std::size_t at) const { return zero_spots_->zero(at / 4); }
  // Floats from entry (f, m, b) to (f, m + 1, b) and to (f + 1, m, b), in every slice.
  std::size_t row() const { return slices_[0].row(); }
  std::size_t plane() const { return slices_[0].plane(); }

 private:
  std::vector<SecondOrderFloatLookup> slices_;
  std::vector<std::array<const float*, 2>> weighted_;  // per slice: middle, back (interpolated lighting)
  double max_length_;
  std::optional<ZeroSpots> zero_spots_;  // over every slice and table
};

// The float path: per segment the cell's eight values (and, lit, their
// gradients) are read once and its three samples evaluated from them in
// float (the front in its own cell too, not carried over from the previous
// one, so that skipping a segment changes no byte); lookups, shading
// (FloatShading: `sampled` lights the slab with the mean of the three
// gradients, `interpolated` weighs the weighted tables by each sample's
// terms) in float, compositing in double (FrontToBack). The traversal stays
// in double, so the segments are the double path's.
template <class Value>
Rgba march_cells_float(const GridVolume& volume, const Value* values, const DualFloatLookup& table,
                       const FloatShading* shading, bool interpolated, const Ray& ray, const Leap& leap) {
  const auto whole = volume.clip(ray);
  if (!whole) return {0, 0, 0, 0};
  const Interval iv = owned_part(*whole);  // all of it unless a brick (GridVolume::Brick)
  const std::size_t sy = volume.dims()[0], sz = sy * volume.dims()[1];
  const FloatShading::Vector d = direction(ray);
  SegmentSkip skip(leap, ray, iv.t1);
  FrontToBack acc;
  for_each_cell_segment(volume, ray, iv, [&](const CellSegment& seg) {
    if (acc.T < leap.termination) return false;
    if (skip.skipped(seg)) return true;
    if (leap.cells && leap.cells->transparent(seg.cell[0], seg.cell[1], seg.cell[2])) return true;
    const std::size_t offset = seg.cell[0] + sy * seg.cell[1] + sz * seg.cell[2];
    const std::array<float, 8> c = corners_as_float(values + offset, sy, sz);
    const auto cell_at = [&](double dt) {
      FloatSampler::Cell cell{offset, {}};
      for (int a = 0; a < 3; ++a)
        cell.f[a] = std::clamp(static_cast<float>(seg.local0[a] + dt * seg.local_dir[a]), 0.0f, 1.0f);
      return cell;
    };
    const double length = seg.tb - seg.ta;
    const std::array<FloatSampler::Cell, 3> at = {cell_at(0), cell_at(0.5 * length), cell_at(length)};
    std::array<float, 3> s;
    for (int k = 0; k < 3; ++k) s[k] = FloatSampler::interpolate(c, at[k].f);
    const DualFloatLookup::Spot spot = table.find(length, s[0], s[1], s[2]);
    Float4 e;
    if (!shading) {
      e = table.blend(spot);
    } else if (!interpolated) {
      std::array<FloatShading::Vector, 3> g;
      for (int k = 0; k < 3; ++k) g[k] = shading->gradient(at[k]);
      e = lit_by(shading->terms(mean(g), d), table.blend(spot));
    } else {
      std::array<FloatShading::Terms, 3> t;
      for (int k = 0; k < 3; ++k) t[k] = shading->terms(shading->gradient(at[k]), d);
      e = lit_lagrange(t, table.blend(spot, 0), table.blend(spot, 1), table.blend(spot, 2));
    }
    acc.add(e[0], e[1], e[2], e[3]);
    return true;
  });
  return acc.result();
}

}  // namespace vri::detail
