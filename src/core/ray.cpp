#include "vri/geometry.hpp"

#include <algorithm>
#include <cmath>
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

bool ClipRegion::cut(const Ray& ray, double& t0, double& t1) const {
  for (const ClipPlane& p : planes) {
    const double along = dot(p.normal, ray.dir), at_origin = dot(p.normal, ray.origin) + p.d;
    if (along == 0) {
      if (!(at_origin >= 0)) return false;  // parallel, on the cut side
      continue;
    }
    const double t = -at_origin / along;  // where the ray crosses the plane
    if (along > 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  if (box) {
    const auto in = clip_to_box(ray, box->lo, box->hi);
    if (!in) return false;
    t0 = std::max(t0, in->t0);
    t1 = std::min(t1, in->t1);
  }
  return t1 > t0;
}

PieceRange owned_pieces(const Interval& iv, double len, long long count) {
  const auto first_at_or_after = [&](double t) {  // the first piece whose front is at or after t
    return std::clamp(static_cast<long long>(std::ceil((t - iv.t0) / len)), 0LL, count);
  };
  const long long begin = iv.own0 > iv.t0 ? first_at_or_after(iv.own0) : 0;
  const long long end = iv.own1 < iv.t1 ? first_at_or_after(iv.own1) : count;
  return {begin, std::max(begin, end)};
}

}  // namespace vri
