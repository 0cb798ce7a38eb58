#pragma once
// `vri render` under mpirun (SPEC §11 `--distributed`; distributed/,
// docs/DISTRIBUTED.md): every rank loads the scene, renders its brick, and
// rank 0 writes the composited image. Built when MPI and IceT are found
// (VRI_MPI); otherwise --distributed is an error that says so.
#include <functional>
#include <string>

#include "scene_options.hpp"
#include "vri/image.hpp"
#include "vri/scene.hpp"

namespace vri::cli {

struct DistributedJob {
  std::string scene_file, output;
  const SceneFlags& flags;
  int threads = 0;
  // Rank 0 only: stages the image as the output file (render_command.cpp).
  std::function<void(const Image&, const Scene&)> write;
};

// True when mpirun started this process among several (and MPI is built in).
bool launched_by_mpirun();
// Collective over the mpirun's ranks; returns the exit status. A failure on
// any rank is one line from rank 0 naming that rank, a non-zero exit on
// every rank, and no file.
int run_render_distributed(const DistributedJob& job);

}  // namespace vri::cli
