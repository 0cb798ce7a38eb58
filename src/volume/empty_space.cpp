#include "vri/volume/empty_space.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vri {

EmptySpace::EmptySpace(const MacroCells& cells, const ZeroOpacity& zero)
    : cells_(cells), empty_(cells.count(), 0) {
  const GridVolume& v = cells.volume();
  const double largest = std::max(std::abs(double(v.min_value())), std::abs(double(v.max_value())));
  const double margin = 1e-5 * (double(v.max_value()) - v.min_value() + largest);
  for (std::size_t i = 0; i < empty_.size(); ++i)
    empty_[i] = zero.over(cells.min(i) - margin, cells.max(i) + margin) ? 1 : 0;
}

std::size_t EmptySpace::empty_count() const {
  return static_cast<std::size_t>(std::count(empty_.begin(), empty_.end(), std::uint8_t{1}));
}

EmptySpace::Run EmptySpace::run(const Ray& ray, double t, double t_max) const {
  const GridVolume& v = cells_.volume();
  const auto& n = v.dims();
  const auto& m = cells_.dims();
  const Vec3 p = ray.at(t);
  int cell[3], step[3];
  double width[3], inverse[3];  // macro cell width, world units; 1 / ray direction
  for (int a = 0; a < 3; ++a) {
    // The grid cell that GridVolume::sample interpolates in, and its macro cell.
    const double u = std::clamp((p[a] - v.origin()[a]) / v.spacing()[a], 0.0, double(n[a] - 1));
    cell[a] = std::min(static_cast<int>(u), n[a] - 2) / MacroCells::kCells;
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
  double leave[3] = {exit(0), exit(1), exit(2)};
  const auto next = [&] {  // the axis whose face the ray crosses first
    return leave[0] <= leave[1] ? (leave[0] <= leave[2] ? 0 : 2) : (leave[1] <= leave[2] ? 1 : 2);
  };
  // Walk while the cells are as the first one (empty or not): the run ends where that changes.
  const bool is_empty = empty(cells_.index(cell[0], cell[1], cell[2]));
  for (;;) {
    const int a = next();
    if (leave[a] >= t_max) return {is_empty, t_max};
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= m[a]) return {is_empty, t_max};
    if (empty(cells_.index(cell[0], cell[1], cell[2])) != is_empty) return {is_empty, leave[a]};
    leave[a] = exit(a);
  }
}

}  // namespace vri
