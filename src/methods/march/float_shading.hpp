#pragma once
// SPEC §5 shading on the float paths (issue 8): HeadlightShader's terms
// c_lit = c a + b, with a = ka + kd x, b = ks x^p, x = |N . d|, in float, the
// gradient interpolated trilinearly in float from GradientField's vectors in
// the cell FloatSampler finds (the same cell and fractions as the scalar
// sample). pow by pow_unit (float_math.hpp), so the 8-lane packets
// (float_packet.cpp) can do the same operations. Against the double shader a
// term differs by a few float roundings.
#include <array>
#include <cmath>

#include "float_math.hpp"
#include "vri/geometry.hpp"
#include "shading/headlight_shader.hpp"
#include "vri/lighting.hpp"
#include "volume/float_sampler.hpp"

namespace vri::detail {

class FloatShading {
 public:
  FloatShading(const Lighting& lighting, const HeadlightShader& shader, const FloatSampler& sampler)
      : g_(shader.gradients().data()),
        sy_(3 * sampler.stride_y()),
        sz_(3 * sampler.stride_z()),
        ka_(static_cast<float>(lighting.ambient)),
        kd_(static_cast<float>(lighting.diffuse)),
        ks_(static_cast<float>(lighting.specular)),
        p_(static_cast<float>(lighting.shininess)),
        flat_(static_cast<float>(shader.flat_threshold())) {}

  using Vector = std::array<float, 3>;
  // The gradient in the cell of a sample.
  Vector gradient(const FloatSampler::Cell& cell) const {
    const float* g = g_ + 3 * cell.offset;
    Vector out;
    for (int a = 0; a < 3; ++a)
      out[a] = FloatSampler::interpolate({g[a], g[3 + a], g[sy_ + a], g[sy_ + 3 + a], g[sz_ + a], g[sz_ + 3 + a],
                                          g[sz_ + sy_ + a], g[sz_ + sy_ + 3 + a]},
                                         cell.f);
    return out;
  }
  struct Terms {
    float a, b;
  };
  // Where |g| is below the flat threshold there is no normal: a = ka + kd, b = 0.
  Terms terms(const Vector& g, const Vector& d) const {
    const float len = std::sqrt((g[0] * g[0] + g[1] * g[1]) + g[2] * g[2]);
    if (!(len >= flat_) || len == 0) return {ka_ + kd_, 0};
    const float x = std::abs((g[0] * d[0] + g[1] * d[1]) + g[2] * d[2]) / len;
    return {ka_ + kd_ * x, ks_ * pow_unit(x, p_)};
  }

  // What the packets read.
  const float* data() const { return g_; }
  std::size_t stride_y() const { return sy_; }  // floats from a grid point to the next along y
  std::size_t stride_z() const { return sz_; }
  float ka() const { return ka_; }
  float kd() const { return kd_; }
  float ks() const { return ks_; }
  float shininess() const { return p_; }
  float flat() const { return flat_; }

 private:
  const float* g_;
  std::size_t sy_, sz_;
  float ka_, kd_, ks_, p_, flat_;
};

// A ray's direction in float, the d of the terms.
inline FloatShading::Vector direction(const Ray& ray) {
  return {static_cast<float>(ray.dir.x), static_cast<float>(ray.dir.y), static_cast<float>(ray.dir.z)};
}

}  // namespace vri::detail
