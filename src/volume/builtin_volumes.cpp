#include "volume/builtin_volumes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "vri/memory.hpp"

namespace vri {

namespace {

// f(i, j, k, index) at every point of the grid, or of the part `region` picks.
template <class F>
GridVolume generate(std::array<int, 3> dims, F&& f, const RegionChooser& region) {
  GridVolume::checked_sample_count({dims[0], dims[1], dims[2]});
  const GridRegion r = region ? region(dims) : GridRegion{{0, 0, 0}, {dims[0] - 1, dims[1] - 1, dims[2] - 1}};
  check_region(r, dims);
  const std::uint64_t n = r.points();
  check_allocation(n, sizeof(float), "a built-in volume of " + std::to_string(n) + " samples");
  std::vector<float> v(n);
  std::size_t at = 0;
  for (int k = r.lo[2]; k <= r.hi[2]; ++k)
    for (int j = r.lo[1]; j <= r.hi[1]; ++j)
      for (int i = r.lo[0]; i <= r.hi[0]; ++i, ++at) {
        const std::size_t idx = std::size_t(i) + std::size_t(dims[0]) * (std::size_t(j) + std::size_t(dims[1]) * k);
        v[at] = static_cast<float>(f(i, j, k, idx));
      }
  if (region) return make_part(std::move(v), dims, r);
  return GridVolume(dims, std::move(v));
}

// splitmix64: a well-mixed counter-based generator.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

}  // namespace

GridVolume marschner_lobb(std::array<int, 3> dims, double f_m, double alpha, const RegionChooser& region) {
  using std::numbers::pi;
  return generate(dims, [&](int i, int j, int k, std::size_t) {
    const double x = -1 + 2.0 * i / (dims[0] - 1);
    const double y = -1 + 2.0 * j / (dims[1] - 1);
    const double z = -1 + 2.0 * k / (dims[2] - 1);
    const double r = std::sqrt(x * x + y * y);
    const double rho_r = std::cos(2 * pi * f_m * std::cos(pi * r / 2));
    return (1 - std::sin(pi * z / 2) + alpha * (1 + rho_r)) / (2 * (1 + alpha));
  }, region);
}

GridVolume sphere_distance(std::array<int, 3> dims, double radius, const RegionChooser& region) {
  if (radius <= 0) radius = (std::min({dims[0], dims[1], dims[2]}) - 1) / 4.0;
  return generate(dims, [&](int i, int j, int k, std::size_t) {
    const double x = i - (dims[0] - 1) / 2.0, y = j - (dims[1] - 1) / 2.0,
                 z = k - (dims[2] - 1) / 2.0;
    return std::sqrt(x * x + y * y + z * z) - radius;
  }, region);
}

GridVolume random_field(std::array<int, 3> dims, std::uint64_t seed, const RegionChooser& region) {
  const std::uint64_t key = splitmix64(seed);
  return generate(dims, [&](int, int, int, std::size_t idx) {
    return (splitmix64(key ^ idx) >> 40) * 0x1.0p-24;  // 24 bits: exact in float, < 1
  }, region);
}

}  // namespace vri
