#include "distributed_render.hpp"

#include <chrono>
#include <exception>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include "brick_volume.hpp"
#include "icet_compositor.hpp"
#include "kd_bricks.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"

namespace vri::distributed {

std::uint64_t fingerprint(std::uint64_t seed, std::string_view bytes) {
  std::uint64_t h = seed ^ 0xcbf29ce484222325ULL;  // FNV-1a
  for (const char c : bytes) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

namespace {

// The methods whose pieces split exactly at brick faces.
void check_method(const Scene& scene) {
  const std::string& m = scene.method.name;
  if (!std::holds_alternative<GridVolume>(scene.volume))
    throw Error("distributed rendering takes grid scenes; tetrahedral meshes are not split yet (docs/DISTRIBUTED.md)");
  if (!known_method(m).distributed)
    throw Error("method '" + m + "' is not distributed: use " +
                method_names([](const MethodInfo& i) { return i.distributed; }, "or"));
  if (scene.method.fast.termination != 0)
    throw Error("early ray termination is per process in distributed rendering and would change the image: "
                "set termination 0");
  // The paper's strategies accept a step by its error times the transmittance
  // in front (Campagnolo et al.'s Algorithm 3), which a brick does not know:
  // 2 ranks left neghip 1.7e-2 from one process at tolerance 1e-3 (issue 46).
  if (m == "adaptive" && scene.method.strategy != "guaranteed")
    throw Error("adaptive --strategy " + scene.method.strategy +
                " takes its steps by the transmittance in front, which a brick does not know: distributed, use "
                "--strategy guaranteed (docs/DISTRIBUTED.md)");
}

// The process's peak resident set (VmHWM in /proc/self/status), bytes.
std::size_t peak_rss() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;  // "VmHWM:  1234 kB"
  return 0;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void check_same_job(const MpiWorld& world, std::uint64_t fingerprint) {
  const std::vector<std::uint64_t> prints = world.all_gather(fingerprint);
  std::optional<std::string> mismatch;
  if (prints[world.rank()] != prints[0])
    mismatch = "its build, scene or flags differ from rank 0's (run the same vri and scene on every rank)";
  world.agree(mismatch);
}

DistributedImage render_distributed(const MpiWorld& world, const Scene& scene, const RenderOptions& options) {
  // This rank's brick and the renderer on it (which keeps a reference to its scene).
  struct Part {
    KdBricks bricks;
    Scene scene;
    std::unique_ptr<const SceneRenderer> renderer;
  };
  DistributedImage out;
  const auto part = world.agreed([&] {
    check_method(scene);
    // The part read by brick_region (PartialLoad) now owns its brick's cells.
    const GridVolume& grid = scene.grid();
    if (!grid.brick()) throw Error("render_distributed takes the part of the grid brick_region picks (PartialLoad)");
    KdBricks bricks(grid.brick()->whole_dims, world.size());
    Scene local = scene;
    own_cells(std::get<GridVolume>(local.volume), bricks.brick(world.rank()));
    auto p = std::make_shared<Part>(Part{std::move(bricks), std::move(local), nullptr});
    p->renderer = std::make_unique<const SceneRenderer>(p->scene);
    return p;
  });
  out.brick_bytes = part->scene.grid().bytes();

  const auto start = std::chrono::steady_clock::now();
  const Image partial = world.agreed([&] { return part->renderer->render(options); });
  out.render_seconds = seconds_since(start);

  const auto composite_start = std::chrono::steady_clock::now();
  const GridVolume& grid = scene.grid();
  const std::vector<int> order = part->bricks.front_to_back(scene.camera, grid.whole_lo(), grid.spacing());
  out.image = world.agreed([&] { return IceTCompositor(world.comm()).composite(partial, order); });
  out.composite_seconds = seconds_since(composite_start);
  out.peak_rss = peak_rss();
  return out;
}

}  // namespace vri::distributed
