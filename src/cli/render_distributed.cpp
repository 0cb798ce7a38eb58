#include "render_distributed.hpp"

#include <iostream>

#include "vri/error.hpp"

#ifdef VRI_DISTRIBUTED
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>

#include "brick_volume.hpp"
#include "distributed_render.hpp"
#include "kd_bricks.hpp"
#include "mpi_world.hpp"
#include "vri/render.hpp"
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

// Not read_file: /proc files report size 0, and a missing scene must not
// throw here, before the first collective (load_scene says so, agreed).
std::string file_bytes(const std::string& path) {
  std::error_code ec;  // a FIFO would block here; load_scene refuses it after
  if (const auto st = std::filesystem::status(path, ec); !ec && !std::filesystem::is_regular_file(st)) return {};
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The build, the scene file and the command line: equal on every rank of a
// consistent job (Linux's /proc/self/cmdline holds the arguments). Not the
// program's own name, argv[0]: the same binary reached through a link was
// refused as another build (issue 47); the build is its version and time.
std::uint64_t job_fingerprint(const std::string& scene_file) {
  std::uint64_t h = distributed::fingerprint(0, std::string(kVersion) + " " + __DATE__ + " " + __TIME__);
  h = distributed::fingerprint(h, file_bytes(scene_file));
  const std::string cmdline = file_bytes("/proc/self/cmdline");
  const std::size_t arguments = cmdline.find('\0');
  return distributed::fingerprint(h, arguments == std::string::npos ? std::string() : cmdline.substr(arguments + 1));
}

}  // namespace

bool launched_by_mpirun() { return distributed::MpiWorld::launched_with_several_ranks(); }

int run_render_distributed(const DistributedJob& job) {
  distributed::MpiWorld world;
  try {
    distributed::check_same_job(world, job_fingerprint(job.scene_file));
    // Each rank reads its brick alone: the k-d split of the grid's dims, the
    // ghost layer of the method the flags leave.
    const PartialLoad part{
        .region =
            [&](std::array<int, 3> dims, const MethodSpec& method) {
              MethodSpec m = method;
              apply_method_overrides(m, job.flags.overrides);
              const distributed::KdBricks bricks(dims, world.size());
              return distributed::brick_region(bricks.brick(world.rank()), dims, distributed::ghost_points(m));
            },
        .value_range =
            [&](float lo, float hi) {
              world.agree(std::nullopt);  // every rank read its part
              return world.all_min_max(lo, hi);
            }};
    const Scene scene = world.agreed([&] {
      if (job.flags.parsed_backend() != Backend::Cpu) throw Error("--distributed renders on the CPU backend only");
      return job.flags.load(job.scene_file, &part);
    });
    const distributed::DistributedImage result =
        distributed::render_distributed(world, scene, {.threads = job.threads});
    const std::vector<std::uint64_t> bytes = world.all_gather(result.brick_bytes);
    const std::vector<std::uint64_t> rss = world.all_gather(result.peak_rss);
    if (world.rank() != 0) return 0;
    job.write(result.image, scene);
    const Camera camera(scene.camera);
    if (const auto cause = transparency_cause(result.image, scene, camera))
      std::cerr << "vri: warning: every pixel is transparent: " << *cause << "\n";
    const std::uint64_t largest = *std::max_element(bytes.begin(), bytes.end());
    const std::uint64_t largest_rss = *std::max_element(rss.begin(), rss.end());
    std::cerr << "vri: rendered " << camera.width() << "x" << camera.height() << " with '" << scene.method.name
              << "' on " << world.size() << " ranks: rank 0 rendered its brick in " << result.render_seconds
              << " s, composited in " << result.composite_seconds << " s; largest brick " << largest
              << " bytes, largest peak memory of a rank " << largest_rss << " bytes -> " << job.output << "\n";
    return 0;
  } catch (const distributed::MpiWorld::JobFailed& e) {
    // One line, from rank 0, naming the rank that failed; the others wait
    // until it is out: mpirun ends the job at the first non-zero exit, which
    // could otherwise come before rank 0 has written it.
    if (world.rank() == 0) std::cerr << "vri: error: " << message_line(e.what()) << std::endl;
    MPI_Barrier(world.comm());
    return 1;
  }
}

#endif

}  // namespace vri::cli
