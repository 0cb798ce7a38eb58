#include "render_distributed.hpp"

#include <iostream>

#include "vri/core/error.hpp"

#ifdef VRI_DISTRIBUTED
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

#include "distributed_render.hpp"
#include "mpi_world.hpp"
#include "vri/render/render_checks.hpp"
#include "vri/version.hpp"
#endif

namespace vri::cli {

#ifndef VRI_DISTRIBUTED

bool launched_by_mpirun() { return false; }

int run_render_distributed(const DistributedJob&) {
  throw Error("--distributed: this vri was built without MPI and IceT (install libopenmpi-dev openmpi-bin "
              "paraview-dev and rebuild; docs/DISTRIBUTED.md)");
}

#else

namespace {

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The build, the scene file and the command line: equal on every rank of a
// consistent job (Linux's /proc/self/cmdline holds the arguments).
std::uint64_t job_fingerprint(const std::string& scene_file) {
  std::uint64_t h = distributed::fingerprint(0, std::string(kVersion) + " " + __DATE__ + " " + __TIME__);
  h = distributed::fingerprint(h, file_bytes(scene_file));
  return distributed::fingerprint(h, file_bytes("/proc/self/cmdline"));
}

}  // namespace

bool launched_by_mpirun() { return distributed::MpiWorld::launched_with_several_ranks(); }

int run_render_distributed(const DistributedJob& job) {
  distributed::MpiWorld world;
  try {
    std::optional<Scene> scene;
    std::optional<std::string> failure;
    try {
      scene.emplace(job.flags.load(job.scene_file));
      if (job.flags.parsed_backend() != Backend::Cpu)
        throw Error("--distributed renders on the CPU backend only");
    } catch (const std::exception& e) {
      failure = e.what();
    }
    world.agree(failure);
    const distributed::DistributedImage result =
        distributed::render_distributed(world, *scene, job_fingerprint(job.scene_file), {.threads = job.threads});
    const std::vector<std::uint64_t> bytes = world.all_gather(result.brick_bytes);
    if (world.rank() != 0) return 0;
    job.write(result.image, *scene);
    const Camera camera(scene->camera);
    if (const auto cause = transparency_cause(result.image, *scene, camera))
      std::cerr << "vri: warning: every pixel is transparent: " << *cause << "\n";
    std::size_t largest = 0;
    for (const std::uint64_t b : bytes) largest = std::max<std::size_t>(largest, b);
    std::cerr << "vri: rendered " << camera.width() << "x" << camera.height() << " with '" << scene->method.name
              << "' on " << world.size() << " ranks: rank 0 rendered its brick in " << result.render_seconds
              << " s, composited in " << result.composite_seconds << " s; largest brick " << largest
              << " bytes -> " << job.output << "\n";
    return 0;
  } catch (const Error&) {
    if (world.rank() == 0) throw;  // one line, from rank 0, naming the rank that failed
    return 1;
  }
}

#endif

}  // namespace vri::cli
