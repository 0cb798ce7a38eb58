#pragma once
// The factory from a MethodSpec to an Integrator over a regular grid.
#include <memory>
#include <string>
#include <vector>

#include "vri/integrators/integrator.hpp"
#include "vri/integrators/method_spec.hpp"
#include "vri/mesh/tet_mesh.hpp"
#include "vri/shading/lighting.hpp"
#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

// vri::Error unless the method (vri/methods.hpp) renders regular grids
// (mesh false) or tetrahedral meshes (mesh true).
void check_volume_kind(const MethodSpec& spec, bool mesh);

// vri::Error if `spec` asks for jitter (MethodSpec::jitter) of a method without it (vri/methods.hpp).
void check_jitter(const MethodSpec& spec);

// vri::Error if `spec` asks for early ray termination of a method without it.
void check_termination(const MethodSpec& spec);
// vri::Error if `spec` asks for early ray termination on a tetrahedral mesh
// (no mesh method has it yet), on the CPU or the GPU.
void check_mesh_termination(const MethodSpec& spec);

// Throws vri::Error for an unknown method (vri/methods.hpp), one that does
// not render this kind of volume, or bad parameters. The integrator refers to `volume` and `tf`: keep them alive.
std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const GridVolume& volume,
                                            const TransferFunction& tf, const Lighting& lighting = {});

// The same over a tetrahedral mesh (exact, tet-raycast); a grid-only method is refused,
// and so is `pt`, which renders whole images (render_projected), not rays.
std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const TetMesh& mesh,
                                            const TransferFunction& tf, const Lighting& lighting = {});

}  // namespace vri
