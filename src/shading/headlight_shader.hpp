#pragma once
// HeadlightShader (SPEC §5): two-sided Blinn-Phong with the light at the eye,
// L = V = H = -d, so with x = |N . d|
//   c_lit = c (ka + kd x) + ks x^p,
// written here as c_lit = c * a + b. N is the normalised gradient; where the
// gradient is shorter than 1e-6 (max - min) per voxel unit there is no usable
// normal and c_lit = c (ka + kd). On tetrahedral meshes the caller supplies
// the gradient (PointGradients) and the threshold is per unit length.
#include <optional>

#include "vri/geometry.hpp"
#include "vri/lighting.hpp"
#include "volume/gradient_field.hpp"
#include "vri/volume.hpp"

namespace vri {

class HeadlightShader {
 public:
  struct Terms {
    double a, b;  // c_lit = c * a + b
  };

  // Throws vri::Error for negative coefficients or shininess.
  HeadlightShader(const Lighting& lighting, const GridVolume& volume);
  // Without a grid (meshes): only terms() is available, gradients() and at() are not.
  HeadlightShader(const Lighting& lighting, double flat_threshold);

  Terms terms(Vec3 gradient, Vec3 dir) const;
  Terms at(Vec3 p, Vec3 dir) const { return terms(gradients_->sample(p), dir); }
  // The largest a + b can be: bounds c_lit for chromaticities in [0, 1].
  double max_brightness() const { return ka_ + kd_ + ks_; }
  const GradientField& gradients() const { return *gradients_; }
  double flat_threshold() const { return flat_; }

 private:
  double ka_, kd_, ks_, p_;
  double flat_;  // |gradient| below this has no normal
  std::optional<GradientField> gradients_;
};

}  // namespace vri
