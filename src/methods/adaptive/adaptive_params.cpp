#include "adaptive_params.hpp"

#include "adaptive_guaranteed.hpp"
#include "adaptive_simpson.hpp"
#include "vri/error.hpp"

namespace vri {

AdaptiveStrategy parse_adaptive_strategy(const std::string& name) {
  if (name == "coupled") return AdaptiveStrategy::Coupled;
  if (name == "decoupled") return AdaptiveStrategy::Decoupled;
  if (name == "guaranteed") return AdaptiveStrategy::Guaranteed;
  throw Error("adaptive: unknown strategy '" + name + "' (known: coupled, decoupled, guaranteed)");
}

void AdaptiveParams::validate() const {
  if (!(tolerance >= 1e-9 && tolerance <= 0.5))
    throw Error("adaptive: tolerance must be in [1e-9, 0.5], got " + format_g(tolerance));
  if (!(hmin >= 1e-3 && hmin <= h0 && h0 <= hmax && hmax <= 1e3))
    throw Error("adaptive: need 1e-3 <= hmin <= h0 <= hmax <= 1e3 voxel units, got hmin " +
                std::to_string(hmin) + ", h0 " + std::to_string(h0) + ", hmax " + std::to_string(hmax));
}

std::unique_ptr<Integrator> make_adaptive(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                          const Lighting& lighting) {
  const AdaptiveParams p{spec.tolerance, spec.h0, spec.hmin, spec.hmax, parse_adaptive_strategy(spec.strategy)};
  if (p.strategy == AdaptiveStrategy::Guaranteed)
    return std::make_unique<GuaranteedAdaptiveIntegrator>(volume, tf, p, lighting);
  return std::make_unique<AdaptiveSimpsonIntegrator>(volume, tf, p, lighting, spec.fast);
}

}  // namespace vri
