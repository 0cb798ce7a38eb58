#include "icet_compositor.hpp"

#include <IceT.h>
#include <IceTMPI.h>

#include <cstdio>
#include <string>

#include "vri/error.hpp"

namespace vri::distributed {

struct IceTCompositor::Context {
  IceTContext icet;
};

IceTCompositor::IceTCompositor(MPI_Comm comm) : context_(new Context) {
  MPI_Comm_rank(comm, &rank_);
  const IceTCommunicator icet_comm = icetCreateMPICommunicator(comm);
  context_->icet = icetCreateContext(icet_comm);
  icetDestroyMPICommunicator(icet_comm);  // the context keeps its own duplicate
  icetDiagnostics(ICET_DIAG_ERRORS | ICET_DIAG_ALL_NODES);
  icetSetColorFormat(ICET_IMAGE_COLOR_RGBA_FLOAT);
  icetSetDepthFormat(ICET_IMAGE_DEPTH_NONE);
  icetCompositeMode(ICET_COMPOSITE_MODE_BLEND);
  icetEnable(ICET_ORDERED_COMPOSITE);
  icetStrategy(ICET_STRATEGY_SEQUENTIAL);  // one tile: the single-image strategy does the work
  icetSingleImageStrategy(ICET_SINGLE_IMAGE_STRATEGY_AUTOMATIC);
  // Every rank's image may cover every pixel: its bounds are the whole view
  // volume under identity matrices.
  icetBoundingBoxd(-1, 1, -1, 1, -1, 1);
}

IceTCompositor::~IceTCompositor() {
  icetDestroyContext(context_->icet);
  delete context_;
}

Image IceTCompositor::composite(const Image& partial, const std::vector<int>& front_to_back) const {
  icetSetContext(context_->icet);
  const int W = partial.width(), H = partial.height();
  icetResetTiles();
  icetAddTile(0, 0, W, H, 0);
  std::vector<IceTInt> order(front_to_back.begin(), front_to_back.end());
  icetCompositeOrder(order.data());
  const IceTDouble identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  const IceTFloat background[4] = {0, 0, 0, 0};
  const IceTImage result =
      icetCompositeImage(partial.data().data(), nullptr, nullptr, identity, identity, background);
  if (const IceTEnum e = icetGetError(); e != ICET_NO_ERROR)
    throw Error("IceT compositing failed (error 0x" + [e] {
      char hex[16];
      std::snprintf(hex, sizeof hex, "%x", static_cast<unsigned>(e));
      return std::string(hex);
    }() + ")");
  if (rank_ != 0) return {};
  Image image(W, H);
  icetImageCopyColorf(result, image.data().data(), ICET_IMAGE_COLOR_RGBA_FLOAT);
  return image;
}

}  // namespace vri::distributed
