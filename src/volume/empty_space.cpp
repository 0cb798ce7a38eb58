#include "vri/volume/empty_space.hpp"

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

std::size_t EmptySpace::empty_count() const {
  return static_cast<std::size_t>(std::count(empty_.begin(), empty_.end(), std::uint8_t{1}));
}

EmptySpace::Run EmptySpace::run(const Ray& ray, double t, double t_max) const {
  if (whole_) return walk(ray, t, t_max);
  // Outside the box of the non-empty macro cells, [b0, b1] along the ray,
  // every macro cell is empty: the walk covers the box only. A run that
  // reaches b1 empty is empty to t_max; one that starts before b0 is empty
  // to b0 at least, the face the walk would have found there (b0 is
  // computed as walk() computes its faces).
  const GridVolume& v = cells_.volume();
  const auto face = [&](int a, int f) {
    return (v.origin()[a] + f * (MacroCells::kCells * v.spacing()[a]) - ray.origin[a]) * (1 / ray.dir[a]);
  };
  double b0, b1;
  if (!occupied_span(ray, face, b0, b1) || t >= b1 || b0 >= t_max) return {true, t_max};
  const double limit = std::min(t_max, b1);
  const Run r = walk(ray, std::max(t, b0), limit);
  if (t < b0 && !r.empty) return {true, b0};
  if (r.t_end >= limit) return {r.empty, r.empty ? t_max : limit};
  return r;
}

EmptySpace::Run EmptySpace::walk(const Ray& ray, double t, double t_max) const {
  const GridVolume& v = cells_.volume();
  const auto& m = cells_.dims();
  std::array<int, 3> cell = macro_cell_at(v, ray.at(t));
  int step[3];
  double width[3], inverse[3];  // macro cell width, world units; 1 / ray direction
  for (int a = 0; a < 3; ++a) {
    step[a] = ray.dir[a] > 0 ? 1 : ray.dir[a] < 0 ? -1 : 0;
    width[a] = MacroCells::kCells * v.spacing()[a];
    inverse[a] = step[a] != 0 ? 1 / ray.dir[a] : 0;
  }
  // t at which the ray leaves the current macro cell through the face on axis a.
  const auto exit = [&](int a) {
    if (step[a] == 0) return std::numeric_limits<double>::infinity();
    const double face = v.origin()[a] + (cell[a] + (step[a] > 0 ? 1 : 0)) * width[a];
    return (face - ray.origin[a]) * inverse[a];
  };
  // Walk while the cells are as the first one (empty or not): the run ends where that changes.
  std::size_t index = cells_.index(cell[0], cell[1], cell[2]);
  const bool is_empty = empty(index);
  const std::ptrdiff_t stride[3] = {step[0], step[1] * std::ptrdiff_t{m[0]},
                                    step[2] * std::ptrdiff_t{m[0]} * m[1]};
  Run end{is_empty, t_max};
  // Crosses the face on axis A at t = leave into the next macro cell; false
  // when the walk ends there (`end` says where). One function per axis, so
  // the three exit times and cells stay in registers.
  const auto cross = [&](auto axis, double& leave) {
    constexpr int A = decltype(axis)::value;
    if (leave >= t_max) return false;
    cell[A] += step[A];
    if (cell[A] < 0 || cell[A] >= m[A]) return false;
    index += stride[A];
    if (empty(index) != is_empty) {
      end.t_end = leave;
      return false;
    }
    leave = exit(A);
    return true;
  };
  using X = std::integral_constant<int, 0>;
  using Y = std::integral_constant<int, 1>;
  using Z = std::integral_constant<int, 2>;
  double l0 = exit(0), l1 = exit(1), l2 = exit(2);
  // The face the ray crosses first (the lower axis on ties).
  while (l0 <= l1 ? (l0 <= l2 ? cross(X{}, l0) : cross(Z{}, l2)) : (l1 <= l2 ? cross(Y{}, l1) : cross(Z{}, l2))) {
  }
  return end;
}

EmptySpace::Walk::Walk(const EmptySpace& space, const Ray& ray, double t, double t_max)
    : space_(space), ray_(ray), t_max_(t_max) {
  for (int a = 0; a < 3; ++a) step_[a] = ray.dir[a] > 0 ? 1 : ray.dir[a] < 0 ? -1 : 0;
  // Only the box of the non-empty macro cells is walked (run()): before it a
  // run is empty, after it too.
  const GridVolume& v = space.cells_.volume();
  const auto face = [&](int a, int f) {
    return (v.origin()[a] + f * (MacroCells::kCells * v.spacing()[a]) - ray.origin[a]) / ray.dir[a];
  };
  double b0 = -std::numeric_limits<double>::infinity(), b1 = std::numeric_limits<double>::infinity();
  if (!space.whole_ && (!space.occupied_span(ray, face, b0, b1) || t >= b1 || b0 >= t_max)) {
    tail_ = true;  // one empty run to t_max
    return;
  }
  if (t < b0) t = b0, box_entry_ = b0;
  limit_ = std::min(t_max, b1);
  cell_ = macro_cell_at(v, ray.at(t));
  for (int a = 0; a < 3; ++a) leave_[a] = exit(a);
}

double EmptySpace::Walk::exit(int a) const {
  if (step_[a] == 0) return std::numeric_limits<double>::infinity();
  const GridVolume& v = space_.cells_.volume();
  const double face = v.origin()[a] + (cell_[a] + (step_[a] > 0 ? 1 : 0)) * (MacroCells::kCells * v.spacing()[a]);
  return (face - ray_.origin[a]) / ray_.dir[a];
}

bool EmptySpace::Walk::next(Run& run) {
  if (done_) return false;
  if (tail_) {  // past the box (or no box): empty to t_max
    run = {true, t_max_};
    done_ = true;
    return true;
  }
  const auto& m = space_.cells_.dims();
  const bool is_empty = space_.empty(space_.cells_.index(cell_[0], cell_[1], cell_[2]));
  if (box_entry_ > -std::numeric_limits<double>::infinity()) {  // the empty run before the box
    const double entry = box_entry_;
    box_entry_ = -std::numeric_limits<double>::infinity();
    if (!is_empty) {
      run = {true, entry};
      return true;
    }
  }
  for (;;) {
    // The face crossed first (the lower axis on ties).
    const int a = leave_[0] <= leave_[1] ? (leave_[0] <= leave_[2] ? 0 : 2) : (leave_[1] <= leave_[2] ? 1 : 2);
    const double leave = leave_[a];
    cell_[a] += step_[a];
    if (leave >= limit_ || cell_[a] < 0 || cell_[a] >= m[a]) {
      // The walk's end: an empty run lasts to t_max, a non-empty one ends at
      // the box (or t_max), and what follows it is empty.
      if (is_empty || limit_ >= t_max_) {
        run = {is_empty, t_max_};
        done_ = true;
      } else {
        run = {false, limit_};
        tail_ = true;
      }
      return true;
    }
    leave_[a] = exit(a);
    if (space_.empty(space_.cells_.index(cell_[0], cell_[1], cell_[2])) != is_empty) {
      run = {is_empty, leave};
      return true;
    }
  }
}

}  // namespace vri
