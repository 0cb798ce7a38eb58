#pragma once
// SlabRgba: the premultiplied (C, alpha) of SPEC §4 over one piece of a ray,
// and the front-to-back "over" operator that joins adjacent pieces. Over is
// associative, which is what lets the table builders reuse partial integrals.
namespace vri {

struct SlabRgba {
  double r = 0, g = 0, b = 0, a = 0;
};

// `front` seen in front of `back`.
inline SlabRgba over(const SlabRgba& front, const SlabRgba& back) {
  const double t = 1 - front.a;
  return {front.r + t * back.r, front.g + t * back.g, front.b + t * back.b, front.a + t * back.a};
}

// A table entry (4 floats r, g, b, alpha) set to v, rounded to float.
inline void store(float* entry, const SlabRgba& v) {
  entry[0] = static_cast<float>(v.r);
  entry[1] = static_cast<float>(v.g);
  entry[2] = static_cast<float>(v.b);
  entry[3] = static_cast<float>(v.a);
}

}  // namespace vri
