#include "vri/integrators/adaptive_params.hpp"

#include "vri/core/error.hpp"
#include "vri/core/printable.hpp"

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

}  // namespace vri
