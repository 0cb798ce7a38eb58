#include "volume/empty_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>

namespace vri {

namespace {

// The macro cell of the grid cell that GridVolume::sample reads at world point p.
std::array<int, 3> macro_cell_at(const GridVolume& v, Vec3 p) {
  std::array<int, 3> m = v.cell_at(v.grid_position(p)).index;
  for (int& i : m) i /= MacroCells::kCells;
  return m;
}

}  // namespace

double interpolation_margin(const GridVolume& v) {
  const double largest = std::max(std::abs(double(v.min_value())), std::abs(double(v.max_value())));
  return 1e-5 * (double(v.max_value()) - v.min_value() + largest);
}

EmptySpace::EmptySpace(const MacroCells& cells, const ZeroOpacity& zero)
    : cells_(cells), empty_(cells.count(), 0) {
  const double margin = interpolation_margin(cells.volume());
  for (std::size_t i = 0; i < empty_.size(); ++i)
    empty_[i] = zero.over(cells.min(i) - margin, cells.max(i) + margin) ? 1 : 0;
  const auto& m = cells.dims();
  box_lo_ = m;
  box_hi_ = {0, 0, 0};
  for (int k = 0; k < m[2]; ++k)
    for (int j = 0; j < m[1]; ++j)
      for (int i = 0; i < m[0]; ++i)
        if (!empty(cells.index(i, j, k))) {
          const int c[3] = {i, j, k};
          for (int a = 0; a < 3; ++a) box_lo_[a] = std::min(box_lo_[a], c[a]), box_hi_[a] = std::max(box_hi_[a], c[a] + 1);
        }
  whole_ = box_lo_ == std::array<int, 3>{0, 0, 0} && box_hi_ == m;
}

template <class Face>
bool EmptySpace::occupied_span(const Ray& ray, Face&& face, double& b0, double& b1) const {
  if (!(box_lo_[0] < box_hi_[0])) return false;  // no non-empty macro cell
  const GridVolume& v = cells_.volume();
  const auto& m = cells_.dims();
  constexpr double inf = std::numeric_limits<double>::infinity();
  b0 = -inf, b1 = inf;
  // A face of the box on the grid's face bounds nothing: a point beyond the
  // grid is sampled in the grid's boundary cell (clamped), inside the box.
  for (int a = 0; a < 3; ++a) {
    const bool lo = box_lo_[a] > 0, hi = box_hi_[a] < m[a];
    if (ray.dir[a] > 0) {
      if (lo) b0 = std::max(b0, face(a, box_lo_[a]));
      if (hi) b1 = std::min(b1, face(a, box_hi_[a]));
    } else if (ray.dir[a] < 0) {
      if (hi) b0 = std::max(b0, face(a, box_hi_[a]));
      if (lo) b1 = std::min(b1, face(a, box_lo_[a]));
    } else {  // parallel to the faces: inside the closed slab or never
      const double u = (ray.origin[a] - v.origin()[a]) / (MacroCells::kCells * v.spacing()[a]);
      if ((lo && u < box_lo_[a]) || (hi && u > box_hi_[a])) return false;
    }
  }
  return b0 <= b1;
}

double EmptySpace::macro_face(int axis, int cell) const {
  const GridVolume& v = cells_.volume();
  return v.origin()[axis] + cell * (MacroCells::kCells * v.spacing()[axis]);
}

Box EmptySpace::occupied_box() const {
  const GridVolume& v = cells_.volume();
  if (!(box_lo_[0] < box_hi_[0])) return {v.origin(), v.origin()};
  const Vec3 lo = v.whole_lo(), hi = v.whole_hi();
  Box box;
  for (int a = 0; a < 3; ++a) {
    box.lo[a] = std::clamp(macro_face(a, box_lo_[a]), lo[a], hi[a]);
    box.hi[a] = std::clamp(macro_face(a, box_hi_[a]), lo[a], hi[a]);
  }
  return box;
}

std::vector<Box> EmptySpace::occupied_parts() const {
  const auto& m = cells_.dims();
  int f = 1;  // macro cells a block side
  const auto blocks = [&](int a) { return (m[a] + f - 1) / f; };
  while (std::size_t(blocks(0)) * blocks(1) * blocks(2) > 4096) f *= 2;
  const Box bounds = occupied_box();
  const auto face = [&](int a, int block) {
    return std::clamp(macro_face(a, std::min(block * f, m[a])), bounds.lo[a], bounds.hi[a]);
  };
  const auto occupied = [&](int bx, int by, int bz) {
    for (int k = bz * f; k < std::min(m[2], (bz + 1) * f); ++k)
      for (int j = by * f; j < std::min(m[1], (by + 1) * f); ++j)
        for (int i = bx * f; i < std::min(m[0], (bx + 1) * f); ++i)
          if (!empty(cells_.index(i, j, k))) return true;
    return false;
  };
  std::vector<Box> parts;
  for (int bz = 0; bz < blocks(2); ++bz)
    for (int by = 0; by < blocks(1); ++by)
      for (int bx = 0; bx < blocks(0); ++bx) {
        if (!occupied(bx, by, bz)) continue;
        const int first = bx;  // a run of occupied blocks along x: first .. bx
        while (bx + 1 < blocks(0) && occupied(bx + 1, by, bz)) ++bx;
        parts.push_back({{face(0, first), face(1, by), face(2, bz)}, {face(0, bx + 1), face(1, by + 1), face(2, bz + 1)}});
      }
  return parts;
}

std::size_t EmptySpace::empty_count() const {
  return static_cast<std::size_t>(std::count(empty_.begin(), empty_.end(), std::uint8_t{1}));
}

double EmptySpace::Walk::exit(int a, int cell) const {
  if (step_[a] == 0) return std::numeric_limits<double>::infinity();
  return (space_.macro_face(a, cell + (step_[a] > 0 ? 1 : 0)) - ray_.origin[a]) * inverse_[a];
}

EmptySpace::Walk::Walk(const EmptySpace& space, const Ray& ray, double t, double t_max)
    : space_(space), ray_(ray), t_max_(t_max) {
  for (int a = 0; a < 3; ++a) {
    step_[a] = ray.dir[a] > 0 ? 1 : ray.dir[a] < 0 ? -1 : 0;
    inverse_[a] = step_[a] != 0 ? 1 / ray.dir[a] : 0;
  }
  // Only the box of the non-empty macro cells is walked: before it a
  // run is empty, after it too.
  const GridVolume& v = space.cells_.volume();
  const auto face = [&](int a, int f) {
    return (space.macro_face(a, f) - ray.origin[a]) * inverse_[a];
  };
  double b0 = -std::numeric_limits<double>::infinity(), b1 = std::numeric_limits<double>::infinity();
  if (!space.whole_ && (!space.occupied_span(ray, face, b0, b1) || t >= b1 || b0 >= t_max)) {
    tail_ = true;  // one empty run to t_max
    return;
  }
  if (t < b0) t = b0, box_entry_ = b0;
  limit_ = std::min(t_max, b1);
  cell_ = macro_cell_at(v, ray.at(t));
  index_ = space.cells_.index(cell_[0], cell_[1], cell_[2]);
  for (int a = 0; a < 3; ++a) leave_[a] = exit(a, cell_[a]);
}

bool EmptySpace::Walk::next(Run& run) {
  if (done_) return false;
  if (tail_) {  // past the box (or no box): empty to t_max
    run = {true, t_max_};
    done_ = true;
    return true;
  }
  const bool is_empty = space_.empty(index_);
  if (box_entry_ > -std::numeric_limits<double>::infinity()) {  // the empty run before the box
    const double entry = box_entry_;
    box_entry_ = -std::numeric_limits<double>::infinity();
    if (!is_empty) {
      run = {true, entry};
      return true;
    }
  }
  // The walk's state in locals while it crosses cells (kept in registers:
  // a member array indexed by the axis was kept in memory), written back
  // where the run ends.
  const auto& m = space_.cells_.dims();
  std::array<int, 3> cell = cell_;
  std::size_t index = index_;
  double l[3] = {leave_[0], leave_[1], leave_[2]};
  const std::ptrdiff_t stride[3] = {step_[0], step_[1] * std::ptrdiff_t{m[0]}, step_[2] * std::ptrdiff_t{m[0]} * m[1]};
  bool more = true;  // false: the walk's end
  // Crosses the face on axis A into the next macro cell; false once the run ends (`run` says where).
  const auto cross = [&](auto axis) {
    constexpr int A = decltype(axis)::value;
    const double leave = l[A];
    cell[A] += step_[A];
    if (leave >= limit_ || cell[A] < 0 || cell[A] >= m[A]) {
      // The walk's end: an empty run lasts to t_max, a non-empty one ends at
      // the box (or t_max), and what follows it is empty.
      if (is_empty || limit_ >= t_max_) {
        run = {is_empty, t_max_};
        done_ = true;
      } else {
        run = {false, limit_};
        tail_ = true;
      }
      more = false;
      return false;
    }
    index += stride[A];
    l[A] = exit(A, cell[A]);
    if (space_.empty(index) != is_empty) {
      run = {is_empty, leave};
      return false;
    }
    return true;
  };
  using X = std::integral_constant<int, 0>;
  using Y = std::integral_constant<int, 1>;
  using Z = std::integral_constant<int, 2>;
  // The face crossed first (the lower axis on ties).
  while (l[0] <= l[1] ? (l[0] <= l[2] ? cross(X{}) : cross(Z{})) : (l[1] <= l[2] ? cross(Y{}) : cross(Z{}))) {
  }
  if (more) {
    cell_ = cell, index_ = index;
    for (int a = 0; a < 3; ++a) leave_[a] = l[a];
  }
  return true;
}

}  // namespace vri
