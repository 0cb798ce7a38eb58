#pragma once
// vri/geometry.hpp: Vec3, Rgba, Ray and Interval: the small value types every part shares.

#include <cmath>
#include <array>
#include <limits>
#include <optional>
#include <vector>

// ---- vec3 ------------------------------------------------------------------
// Vec3: the double-precision 3-vector used for points, directions and spacings.

namespace vri {

struct Vec3 {
  double x = 0, y = 0, z = 0;

  constexpr double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
constexpr Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
constexpr Vec3 operator*(double s, Vec3 a) { return a * s; }
constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3 a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalize(Vec3 a) { return a * (1.0 / length(a)); }

}  // namespace vri

// ---- rgba ------------------------------------------------------------------
// Rgba: one pixel's premultiplied (C, alpha) of SPEC §4, in double precision.

namespace vri {

using Rgba = std::array<double, 4>;

}  // namespace vri

// ---- ray -------------------------------------------------------------------
// Ray: x(t) = origin + t * dir with |dir| = 1, so t is world distance (SPEC §4).

namespace vri {

struct Ray {
  Vec3 origin;
  Vec3 dir;
  Vec3 at(double t) const { return origin + t * dir; }
};

struct Interval {
  double t0, t1;
  // Sort-last rendering (GridVolume::Brick, distributed/): this process
  // integrates only the pieces of [t0, t1] (samples, slabs, cells) whose
  // front lies in [own0, own1); by default all of them.
  double own0 = -std::numeric_limits<double>::infinity();
  double own1 = std::numeric_limits<double>::infinity();
  double length() const { return t1 - t0; }
  bool whole() const { return own0 <= t0 && own1 >= t1; }
};

// Of `count` pieces of length `len` cut from iv.t0 (piece k's front at
// t0 + k len; the last may be shorter), the range [begin, end) that iv owns.
// Neighbouring bricks compute their shared bound from the same plane, so
// every piece falls in exactly one brick's range.
struct PieceRange {
  long long begin, end;
};
PieceRange owned_pieces(const Interval& iv, double len, long long count);

// The owned part [max(t0, own0), min(t1, own1)] for methods that walk the
// grid's cells: a brick's window starts and ends on cell faces, so its cells
// are pieces of the whole ray's.
inline Interval owned_part(const Interval& iv) {
  return {iv.t0 > iv.own0 ? iv.t0 : iv.own0, iv.t1 < iv.own1 ? iv.t1 : iv.own1};
}

// An axis-aligned box, the closed set [lo, hi].
struct Box {
  Vec3 lo, hi;
};

// Where a method sees anything (Integrator::footprint): a ray that meets
// none of `parts` (none of `bounds` when there are no parts) integrates to
// exactly {0, 0, 0, 0}. Every part lies in `bounds`.
struct Footprint {
  Box bounds;
  std::vector<Box> parts;
};

// The part of the ray inside the closed box [lo, hi] with t >= 0, if any.
// A ray running exactly along a face is inside (SPEC §1).
std::optional<Interval> clip_to_box(const Ray& ray, Vec3 lo, Vec3 hi);

// ClipRegion (SPEC §12 "clip", issue 50; docs/CLIPPING.md): the part of
// space a render keeps, in world units - where n . p + d >= 0 for every plane
// and inside the box. Convex, so a ray keeps one interval of it; each method
// integrates that interval as it integrates the volume's own box, so its
// last step, slab or cell piece ends at the cut, not at the next step.
struct ClipPlane {
  Vec3 normal;  // any length but 0: the kept side is where it points
  double d = 0;
};
struct ClipRegion {
  std::vector<ClipPlane> planes;
  std::optional<Box> box;
  bool active() const { return !planes.empty() || box.has_value(); }
  // [t0, t1] cut to the kept part of the ray; false where none of it is
  // kept (or only a point). A ray parallel to a plane is kept whole on the
  // kept side, the plane itself included.
  bool cut(const Ray& ray, double& t0, double& t1) const;
};

}  // namespace vri
