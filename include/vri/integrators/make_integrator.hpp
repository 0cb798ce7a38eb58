#pragma once
// The factory from a MethodSpec to an Integrator over a regular grid.
#include <memory>
#include <string>
#include <vector>

#include "vri/integrators/integrator.hpp"
#include "vri/integrators/method_spec.hpp"
#include "vri/shading/lighting.hpp"
#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

// Every method name of SPEC §9, implemented or not.
const std::vector<std::string>& known_method_names();

// Throws vri::Error for an unknown method, one not yet implemented, or bad
// parameters. The integrator refers to `volume` and `tf`: keep them alive.
std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const GridVolume& volume,
                                            const TransferFunction& tf, const Lighting& lighting = {});

}  // namespace vri
