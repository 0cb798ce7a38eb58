#pragma once
// The methods of SPEC §9 and what each supports: the one list the front
// doors read (the CLI's help, the scene's checks, the viewer's menu, the
// Python docstring, the Vulkan and distributed front doors; issue 48).
// Adding a method is its folder (src/methods/<method>/, with its
// constructors) and its row in src/methods/method_registry.cpp.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vri {

class Integrator;
struct MethodSpec;
class GridVolume;
class TetMesh;
class TransferFunction;
struct Lighting;
class GpuSceneRenderer;
struct Scene;

// A method's constructors (pbrt-v4's Create()): each lives in the method's
// folder and parses and checks its own parameters from the MethodSpec.
using GridIntegratorMaker = std::unique_ptr<Integrator> (*)(const MethodSpec&, const GridVolume&,
                                                            const TransferFunction&, const Lighting&);
using MeshIntegratorMaker = std::unique_ptr<Integrator> (*)(const MethodSpec&, const TetMesh&,
                                                            const TransferFunction&, const Lighting&);
using GpuRendererMaker = std::unique_ptr<GpuSceneRenderer> (*)(const Scene&);

struct MethodInfo {
  std::string_view name;
  std::string_view paper;  // the paper (or SPEC section) it implements
  bool grid = false;        // renders regular grids
  bool mesh = false;        // renders tetrahedral meshes
  bool per_ray = true;      // an Integrator per ray (pt, pt-cylindrical project whole cells)
  bool gpu_grid = false;    // --backend vulkan on grids
  bool gpu_mesh = false;    // --backend vulkan on meshes
  bool distributed = false; // mpirun ... --distributed (grids, split at brick faces)
  bool termination = false; // early ray termination (method.termination)
  bool jitter = false;      // a jittered first sample (method.jitter)
  // The parameter that sets how far apart it samples ("step" for the uniform
  // marchers, "hmin" for adaptive's smallest step); empty for the methods
  // that walk cells. The render's work cap and the bricks' ghost layers read it.
  std::string_view step_parameter = {};
  // Its per-ray integrator on a grid and on a mesh, and its GPU renderer (on
  // what gpu_grid and gpu_mesh say; null in a build without Vulkan); null
  // where it has none. make_integrator and the Vulkan backend call them.
  GridIntegratorMaker make_grid = nullptr;
  MeshIntegratorMaker make_mesh = nullptr;
  GpuRendererMaker make_gpu = nullptr;
};

// Every method, in SPEC §9's order.
const std::vector<MethodInfo>& methods();

// The method of that name, or null.
const MethodInfo* find_method(std::string_view name);

// The names of the methods `keep` selects, as "a, b and c" (`conjunction`
// "or": "a, b or c"); all methods when keep is null.
std::string method_names(bool (*keep)(const MethodInfo&) = nullptr, std::string_view conjunction = "and");

// vri::Error "unknown method 'x' (known: ...)" unless the name is one.
const MethodInfo& known_method(std::string_view name);

}  // namespace vri
