#include "shading/headlight_shader.hpp"

#include <algorithm>
#include <cmath>

#include "vri/error.hpp"

namespace vri {

HeadlightShader::HeadlightShader(const Lighting& l, const GridVolume& volume)
    : HeadlightShader(l, 1e-6 * (double(volume.max_value()) - volume.min_value()) / volume.voxel_unit()) {
  gradients_.emplace(volume);
}

HeadlightShader::HeadlightShader(const Lighting& l, double flat_threshold)
    : ka_(l.ambient), kd_(l.diffuse), ks_(l.specular), p_(l.shininess), flat_(flat_threshold) {
  for (double v : {ka_, kd_, ks_, p_})
    if (!(v >= 0) || !std::isfinite(v))
      throw Error("lighting coefficients and shininess must be finite and >= 0");
}

HeadlightShader::Terms HeadlightShader::terms(Vec3 g, Vec3 dir) const {
  const double len = length(g);
  if (!(len >= flat_) || len == 0) return {ka_ + kd_, 0.0};
  // |N.d| <= 1, but rounding can give 1 + ulp, which a huge shininess turns
  // into an overflow (issue 16).
  const double x = std::min(std::abs(dot(g, dir)) / len, 1.0);
  return {ka_ + kd_ * x, ks_ * std::pow(x, p_)};
}

}  // namespace vri
