#pragma once
// Sort-last rendering of a grid scene over the ranks of an mpirun (SPEC §11
// `vri render --distributed`; docs/DISTRIBUTED.md): rank r renders brick r
// of a k-d split (kd_bricks.hpp) - the pieces of every ray that start in it,
// on the whole ray's samples (GridVolume::Brick) - and IceT composites the
// partial images front to back (icet_compositor.hpp). The image equals one
// process's up to float rounding in the compositing.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mpi_world.hpp"
#include "vri/image.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::distributed {

struct DistributedImage {
  Image image;                   // rank 0: the whole image; elsewhere empty
  double render_seconds = 0;     // this rank's own part
  double composite_seconds = 0;  // IceT, this rank's share
  std::size_t brick_bytes = 0;   // this rank's samples
  std::size_t peak_rss = 0;      // this rank's peak resident memory, bytes (Linux VmHWM; 0 elsewhere)
};

// What must agree across ranks: the build, the scene text and the flags.
std::uint64_t fingerprint(std::uint64_t seed, std::string_view bytes);

// Collective, before anything else: throws MpiWorld::JobFailed on every rank
// if some rank's fingerprint differs from rank 0's.
void check_same_job(const MpiWorld& world, std::uint64_t fingerprint);

// Collective. Each rank passes the scene it loaded with its part of the grid
// as brick_region picks it (PartialLoad); a rank that fails anywhere
// (bricking, tables, rendering, compositing) makes every rank throw
// MpiWorld::JobFailed naming it.
DistributedImage render_distributed(const MpiWorld& world, const Scene& scene, const RenderOptions& options);

}  // namespace vri::distributed
