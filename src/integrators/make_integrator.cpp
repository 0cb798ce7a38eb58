#include "vri/integrators/make_integrator.hpp"

#include <algorithm>

#include "vri/core/error.hpp"
#include "vri/integrators/adaptive_guaranteed.hpp"
#include "vri/integrators/adaptive_simpson.hpp"
#include "vri/integrators/exact.hpp"
#include "vri/integrators/riemann.hpp"

namespace vri {

const std::vector<std::string>& known_method_names() {
  static const std::vector<std::string> names = {
      "riemann", "preint1", "preint2", "preint2-dual", "adaptive",
      "exact",   "pt",      "pt-cylindrical", "tet-raycast"};
  return names;
}

std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const GridVolume& volume,
                                            const TransferFunction& tf, const Lighting& lighting) {
  if (spec.name == "riemann") return std::make_unique<RiemannIntegrator>(volume, tf, spec.step, lighting);
  if (spec.name == "adaptive") {
    if (lighting.enabled) throw Error("method 'adaptive' does not support lighting yet");
    const AdaptiveParams p{spec.tolerance, spec.h0, spec.hmin, spec.hmax,
                           parse_adaptive_strategy(spec.strategy)};
    if (p.strategy == AdaptiveStrategy::Guaranteed)
      return std::make_unique<GuaranteedAdaptiveIntegrator>(volume, tf, p);
    return std::make_unique<AdaptiveSimpsonIntegrator>(volume, tf, p);
  }
  if (spec.name == "exact") return std::make_unique<ExactIntegrator>(volume, tf, spec.tolerance, lighting);
  const auto& known = known_method_names();
  if (std::find(known.begin(), known.end(), spec.name) != known.end())
    throw Error("method '" + spec.name + "' is not implemented yet for regular grids");
  std::string list;
  for (const auto& n : known) list += (list.empty() ? "" : ", ") + n;
  throw Error("unknown method '" + spec.name + "' (known: " + list + ")");
}

}  // namespace vri
