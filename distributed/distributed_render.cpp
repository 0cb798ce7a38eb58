#include "distributed_render.hpp"

#include <chrono>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "brick_volume.hpp"
#include "icet_compositor.hpp"
#include "kd_bricks.hpp"
#include "vri/core/error.hpp"
#include "vri/render/scene_renderer.hpp"

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
  if (m != "exact" && m != "riemann" && m != "preint1" && m != "preint2" && m != "preint2-dual" && m != "adaptive")
    throw Error("method '" + m + "' is not distributed: use exact, riemann, preint1, preint2, preint2-dual or adaptive");
  if (scene.method.fast.termination != 0)
    throw Error("early ray termination is per process in distributed rendering and would change the image: "
                "set termination 0");
}

template <class F>
auto step(const MpiWorld& world, F&& f) {
  std::optional<std::string> failure;
  std::optional<decltype(f())> result;
  try {
    result.emplace(f());
  } catch (const std::exception& e) {
    failure = e.what();
  }
  world.agree(failure);
  return std::move(*result);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

DistributedImage render_distributed(const MpiWorld& world, const Scene& scene, std::uint64_t fingerprint,
                                    const RenderOptions& options) {
  const std::vector<std::uint64_t> prints = world.all_gather(fingerprint);
  std::optional<std::string> mismatch;
  if (prints[world.rank()] != prints[0])
    mismatch = "its build, scene or flags differ from rank 0's (run the same vri and scene on every rank)";
  world.agree(mismatch);

  // This rank's brick and the renderer on it (which keeps a reference to its scene).
  struct Part {
    KdBricks bricks;
    Scene scene;
    std::unique_ptr<const SceneRenderer> renderer;
  };
  DistributedImage out;
  const auto part = step(world, [&] {
    check_method(scene);
    const GridVolume& whole = scene.grid();
    KdBricks bricks(whole.dims(), world.size());
    Scene local = scene;
    local.volume = cut_brick(whole, bricks.brick(world.rank()), ghost_points(scene.method));
    auto p = std::make_shared<Part>(Part{std::move(bricks), std::move(local), nullptr});
    p->renderer = std::make_unique<const SceneRenderer>(p->scene);
    return p;
  });
  out.brick_bytes = part->scene.grid().bytes();

  const auto start = std::chrono::steady_clock::now();
  const Image partial = step(world, [&] { return part->renderer->render(options); });
  out.render_seconds = seconds_since(start);

  const auto composite_start = std::chrono::steady_clock::now();
  const GridVolume& whole = scene.grid();
  const std::vector<int> order = part->bricks.front_to_back(scene.camera, whole.origin(), whole.spacing());
  out.image = step(world, [&] { return IceTCompositor(world.comm()).composite(partial, order); });
  out.composite_seconds = seconds_since(composite_start);
  return out;
}

}  // namespace vri::distributed
