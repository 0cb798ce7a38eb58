#pragma once
// vri/methods.hpp: the methods (the registry: one row a paper), a method's parameters (MethodSpec) and the per-ray integrators made from them.

#include <cstdint>
#include <optional>
#include <string>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/volume.hpp"
#include "vri/lighting.hpp"
#include "vri/transfer_function.hpp"

// ---- method_spec -----------------------------------------------------------
// MethodSpec: the "method" block of a scene (SPEC §8, §9) - which integrator
// and its parameters. Step sizes are in voxel units (SPEC §1).

namespace vri {

// preint2*: chords per second-order table entry (El Hajjar et al.'s K) unless a scene says.
inline constexpr int kDefaultSecondOrderIterations = 8;

// FastPath: the speed-ups of the ray casters (riemann, preint1, preint2) that
// change no pixel, or change it by a stated bound (issue 8; docs/PERFORMANCE.md).
// - skip_empty: rays leap over macro cells whose values the transfer function
//   maps to zero opacity (volume/empty_space.hpp); they stay on the same
//   sample positions, so the image is the same bytes as without skipping.
// - termination: a ray stops once its transmittance T falls below this
//   threshold (0: never; SPEC is silent, so it is off unless asked for). What
//   it drops is at most T < termination in alpha, and T times the largest
//   colour (1 for unlit colours) in each colour channel.
// - float_math (riemann, preint1, preint2): sampling, classification or
//   table lookups and shading in float on the same sample positions
//   (methods/riemann/float_riemann.hpp, float_march.hpp, float_shading.hpp),
//   compositing in double (FrontToBack, methods/march/ray_steps.hpp: a float
//   sum's roundings grew with the number of samples), on packets of 8 rays
//   with AVX2 (methods/march/float_packet.hpp): unlit and lit, in both
//   lighting modes of the pre-integrated methods. A pixel differs from the
//   double path's by under 1e-4 per channel on the bundled scenes, and by
//   under 1e-6 at fine steps (tested). Off: the double path, the reference.
struct FastPath {
  bool skip_empty = true;
  double termination = 0;  // transmittance threshold in [0, 1)
  bool float_math = true;
};


struct MethodSpec {
  std::string name = "exact";
  double step = 1.0;         // riemann, preint*: voxel units
  double tolerance = 1e-6;   // exact, adaptive
  int table_size = 256;      // preint*, pt*
  bool table_size_given = false;  // named by the scene or a flag; else preint2-dual uses its own default (64)
  int iterations = kDefaultSecondOrderIterations;  // preint2*: chords per second-order table entry (1..4096)
  int length_samples = 64;   // pt, tet-raycast: lengths in the (l, s_f, s_b) table
  int planes = 0;            // pt-cylindrical: cylinder planes (0: table_size)
  // adaptive (Campagnolo et al. 2015 defaults), voxel units; strategy:
  // coupled, decoupled or guaranteed
  double h0 = 0.5, hmin = 0.1, hmax = 2.0;
  std::string strategy = "coupled";
  // preint*: pre-integration table builder. preint2* use it when it names a
  // second-order builder (plain, fast), else the fast one.
  std::string builder = "incremental";
  // riemann, preint1, preint2: empty-space skipping (`skip_empty`, default on: it changes
  // no pixel) and early ray termination (`termination`, a transmittance
  // threshold; default 0, off). FastPath above.
  FastPath fast{};
  // Caps checked before rendering (issue 17): samples along one ray and
  // samples in all (per ray x pixels); raised by max_samples / max_work.
  double max_samples = 1e7, max_work = 2e10;
  // riemann: the seed of the per-pixel jitter of the first sample (issue 20;
  // riemann.hpp), against wood-grain rings; none: no jitter.
  std::optional<std::uint64_t> jitter{};
};

// The numeric parameters of a method block (SPEC §8), each with one rule,
// checked in one place for a scene file, a command-line flag, a viewer
// message and a Python keyword alike (issue 47): the same value is refused in
// the same words wherever it comes from.
struct MethodParameter {
  std::string_view key;     // method.<key> in a scene
  std::string_view flag;    // the command line's, or empty (a scene key only)
  std::string_view expects; // the rule in words: "a finite number > 0"
  bool (*holds)(double);    // the rule
  double (*of)(const MethodSpec&);  // its value in a MethodSpec
};

// Every numeric parameter of MethodSpec, in its order.
std::span<const MethodParameter> method_parameters();

// vri::Error "method.<key> (<flag>): expected <rule>, found <value>" unless
// `value` keeps the rule of parameter `key` (one of method_parameters()).
void check_method_parameter(std::string_view key, double value);

// check_method_parameter for each numeric parameter of `method`.
void check_method_parameters(const MethodSpec& method);

}  // namespace vri

// ---- methods ---------------------------------------------------------------
// The methods of SPEC §9 and what each supports: the one list the front
// doors read (the CLI's help, the scene's checks, the viewer's menu, the
// Python docstring, the Vulkan and distributed front doors; issue 48).
// Adding a method is its folder (src/methods/<method>/, with its
// constructors) and its row in src/methods/method_registry.cpp.

namespace vri {

class Integrator;
struct MethodSpec;
class GridVolume;
class TetMesh;
class TransferFunction;
struct Lighting;
class GpuSceneRenderer;
class ProjectedSceneRenderer;
struct Scene;

// A method's constructors (pbrt-v4's Create()): each lives in the method's
// folder and parses and checks its own parameters from the MethodSpec.
using GridIntegratorMaker = std::unique_ptr<Integrator> (*)(const MethodSpec&, const GridVolume&,
                                                            const TransferFunction&, const Lighting&);
using MeshIntegratorMaker = std::unique_ptr<Integrator> (*)(const MethodSpec&, const TetMesh&,
                                                            const TransferFunction&, const Lighting&);
using GpuRendererMaker = std::unique_ptr<GpuSceneRenderer> (*)(const Scene&);
using ProjectedRendererMaker = std::unique_ptr<ProjectedSceneRenderer> (*)(const Scene&);

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
  // The method-block keys that shape its image (SPEC §9's parameters, and
  // the table builder where it builds tables): changing any other leaves
  // its bytes as they are (EveryMethod.ReadsTheParametersItListsAndNoOther).
  // max_samples and max_work cap every method; termination, skip_empty,
  // float_math and jitter are the fast path's (the flags above).
  std::vector<std::string_view> parameters = {};
  // Its per-ray integrator on a grid and on a mesh, its whole-cell renderer
  // (per_ray false), and its GPU renderer (on what gpu_grid and gpu_mesh
  // say; null in a build without Vulkan); null where it has none.
  // make_integrator, SceneRenderer and the Vulkan backend call them.
  GridIntegratorMaker make_grid = nullptr;
  MeshIntegratorMaker make_mesh = nullptr;
  ProjectedRendererMaker make_projected = nullptr;
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

// ---- integrator ------------------------------------------------------------
// Integrator: one method of evaluating the volume rendering integral (SPEC §4)
// along one ray. Every per-ray CPU method is a class behind this interface
// (vri/methods.hpp per_ray); pt and pt-cylindrical project whole tetrahedra
// (render_projected) and the GPU has its own kernels (render/backend.hpp). The
// renderer calls integrate() concurrently from several threads, so it is const
// and keeps no mutable state.

namespace vri {

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Premultiplied (C_r, C_g, C_b, alpha) of the ray, before any background.
  virtual Rgba integrate(const Ray& ray) const = 0;
  // out[i] = integrate(rays[i]) for i < n, the same bytes; the renderer hands
  // over two rows of a tile at a time, in blocks of 4 x 2 pixels, so a method
  // may march neighbouring rays together (the packets of 8,
  // methods/march/float_packet.hpp).
  virtual void integrate_row(const Ray* rays, int n, Rgba* out) const {
    for (int i = 0; i < n; ++i) out[i] = integrate(rays[i]);
  }
  // Where the method sees anything: a ray that misses the footprint
  // integrates to exactly {0, 0, 0, 0}, the value an image starts with, so
  // the renderer need not cast it (as VTK's ray casters cast only inside
  // the volume's projected bounds). Null (the default): every ray is cast.
  virtual const Footprint* footprint() const { return nullptr; }
  virtual std::string_view name() const = 0;
};

}  // namespace vri

// ---- error_estimating_integrator -------------------------------------------
// An Integrator that also reports, per ray, its own error estimate, how many
// evaluations it spent and (on request) the steps it took. The adaptive
// methods implement it; `vri render --error-estimate` and the step plots of
// docs/ADAPTIVE.md read it.

namespace vri {

// One accepted Simpson step of the ray (for plots like Campagnolo et al. 2015, Fig. 6).
struct AdaptiveStep {
  bool outer;    // outer (colour) integral, else inner (optical depth)
  double t, h;   // start and length, world units
  double alpha;  // opacity accumulated up to t + h (outer steps; 0 for inner steps)
};

struct RayStats {
  long evaluations = 0;       // transfer-function evaluations (each at one field value)
  Rgba error_estimate{};      // per channel, the accepted steps' error terms, summed
  bool record_steps = false;  // set by the caller to fill `steps`
  std::vector<AdaptiveStep> steps;
};

class ErrorEstimatingIntegrator : public Integrator {
 public:
  // As integrate(ray), adding this ray's figures to `stats`.
  virtual Rgba integrate(const Ray& ray, RayStats& stats) const = 0;
  Rgba integrate(const Ray& ray) const final {
    RayStats stats;
    return integrate(ray, stats);
  }
};

}  // namespace vri

// ---- make_integrator -------------------------------------------------------
// The factory from a MethodSpec to an Integrator over a regular grid.

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
