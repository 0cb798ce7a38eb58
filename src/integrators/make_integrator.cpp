#include "vri/integrators/make_integrator.hpp"

#include <algorithm>

#include "vri/core/error.hpp"
#include "vri/integrators/exact.hpp"
#include "vri/integrators/preint1.hpp"
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
  if (spec.name == "exact") return std::make_unique<ExactIntegrator>(volume, tf, spec.tolerance, lighting);
  if (spec.name == "preint1") {
    if (lighting.enabled) throw Error("preint1: lighting is not supported yet; disable it or use riemann/exact");
    return std::make_unique<Preint1Integrator>(volume, tf, spec.step, spec.table_size, spec.builder);
  }
  const auto& known = known_method_names();
  if (std::find(known.begin(), known.end(), spec.name) != known.end())
    throw Error("method '" + spec.name + "' is not implemented yet for regular grids");
  std::string list;
  for (const auto& n : known) list += (list.empty() ? "" : ", ") + n;
  throw Error("unknown method '" + spec.name + "' (known: " + list + ")");
}

}  // namespace vri
