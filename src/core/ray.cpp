#include "vri/core/ray.hpp"

#include <algorithm>
#include <limits>

namespace vri {

std::optional<Interval> clip_to_box(const Ray& ray, Vec3 lo, Vec3 hi) {
  double t0 = 0.0;  // only t >= 0 counts (SPEC §4)
  double t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    const double o = ray.origin[a], d = ray.dir[a];
    if (d == 0.0) {
      if (o < lo[a] || o > hi[a]) return std::nullopt;  // parallel and outside
      continue;
    }
    double ta = (lo[a] - o) / d, tb = (hi[a] - o) / d;
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (!(t1 > t0)) return std::nullopt;  // empty or a single touching point
  return Interval{t0, t1};
}

}  // namespace vri
