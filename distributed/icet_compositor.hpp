#pragma once
// Sort-last compositing by IceT (Moreland et al. 2011, the library ParaView
// composites with): every rank hands in its partial image - premultiplied
// float RGBA, its bricks' part of every ray - and IceT blends them with
// `over` in the given front-to-back order (ICET_COMPOSITE_MODE_BLEND,
// ICET_ORDERED_COMPOSITE, radix-k or its automatic choice), the whole image
// landing on rank 0.
#include <vector>

#include <mpi.h>

#include "vri/image.hpp"

namespace vri::distributed {

class IceTCompositor {
 public:
  explicit IceTCompositor(MPI_Comm comm);
  ~IceTCompositor();
  IceTCompositor(const IceTCompositor&) = delete;
  IceTCompositor& operator=(const IceTCompositor&) = delete;

  // Collective. `front_to_back`: every rank once, the nearest first. Returns
  // the composited image on rank 0 and an empty one elsewhere; throws
  // vri::Error if IceT reports an error.
  Image composite(const Image& partial, const std::vector<int>& front_to_back) const;

 private:
  struct Context;
  Context* context_;
  int rank_ = 0;
};

}  // namespace vri::distributed
