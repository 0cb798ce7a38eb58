#pragma once
// RenderCancelled: work stopped from another thread (vri/render/cancellation.hpp):
// a render between its tiles, a table build between its rows.
#include "vri/core/error.hpp"

namespace vri {

class RenderCancelled : public Error {
 public:
  RenderCancelled() : Error("the render was cancelled") {}
};

// In work a Cancellation runs: throws RenderCancelled once it is cancelled.
// The table builders call it after their parallel loops, which a cancel cuts
// short: what they leave half built is then never used, converted or copied.
void throw_if_build_cancelled();

}  // namespace vri
