#include "vri/error.hpp"

#include <tbb/task_group.h>

namespace vri {

void throw_if_build_cancelled() {
  if (tbb::is_current_task_group_canceling()) throw RenderCancelled();
}

}  // namespace vri
