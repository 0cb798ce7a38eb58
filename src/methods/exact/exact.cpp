#include "exact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cubic.hpp"
#include "methods/march/early_stop.hpp"
#include "vri/error.hpp"

namespace vri {

ExactIntegrator::ExactIntegrator(const GridVolume& volume, const TransferFunction& tf, double tolerance,
                                 const Lighting& lighting)
    : volume_(volume), tolerance_(tolerance), pieces_(tf) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + format_g(tolerance));
  if (lighting.enabled) shader_.emplace(lighting, volume);
}

ExactIntegrator::~ExactIntegrator() = default;

Rgba ExactIntegrator::integrate(const Ray& ray) const {
  const auto iv = volume_.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  Accumulator acc;
  // The tolerance is on colours up to 1; lit colours reach max_brightness, and
  // the budget scales with it (issue 16): with specular 1e300 the rounding of
  // |N.d| near its zero alone is far above an absolute 1e-6.
  const double brightest = brightest_colour(shader_);
  const double error_per_length = tolerance_ * brightest / iv->length();
  // What is left after stopping is at most T * (brightest colour) per channel.
  // Not above 1e-7: a brick of a distributed render (GridVolume::Brick)
  // starts at T = 1 and so stops at another place than the whole ray, and
  // the two images must agree within 1e-6 (SPEC §11).
  const double cutoff = std::min(early_stop_transmittance(tolerance_, brightest), 1e-7 / brightest);
  for_each_cell_segment(volume_, ray, owned_part(*iv), [&](const CellSegment& seg) {
    integrate_cell(seg, ray.dir, error_per_length, acc);
    return acc.T > cutoff;
  });
  return {acc.C[0], acc.C[1], acc.C[2], 1 - acc.T};
}

void ExactIntegrator::integrate_cell(const CellSegment& cs, Vec3 dir, double error_per_length,
                                     Accumulator& acc) const {
  const double len = cs.tb - cs.ta;
  const Cubic s = trilinear_along(volume_, cs);
  // Lit: the gradient components along the segment and the sign changes of
  // N.d, where |N.d| has a kink.
  Cubic grad[3];
  double kinks[3];
  int nkinks = 0;
  if (shader_) nkinks = gradient_along(shader_->gradients(), cs, dir, grad, kinks);

  const PieceIntegrator::Lit lit{shader_ ? &*shader_ : nullptr, grad, dir, kinks, nkinks};
  pieces_.integrate(s, len, error_per_length, acc, shader_ ? &lit : nullptr);
}

std::unique_ptr<Integrator> make_exact(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                       const Lighting& lighting) {
  return std::make_unique<ExactIntegrator>(volume, tf, spec.tolerance, lighting);
}

}  // namespace vri
