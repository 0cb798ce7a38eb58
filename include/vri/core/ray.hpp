#pragma once
// Ray: x(t) = origin + t * dir with |dir| = 1, so t is world distance (SPEC §4).
#include <optional>

#include "vri/core/vec3.hpp"

namespace vri {

struct Ray {
  Vec3 origin;
  Vec3 dir;
  Vec3 at(double t) const { return origin + t * dir; }
};

struct Interval {
  double t0, t1;
  double length() const { return t1 - t0; }
};

// The part of the ray inside the closed box [lo, hi] with t >= 0, if any.
// A ray running exactly along a face is inside (SPEC §1).
std::optional<Interval> clip_to_box(const Ray& ray, Vec3 lo, Vec3 hi);

}  // namespace vri
