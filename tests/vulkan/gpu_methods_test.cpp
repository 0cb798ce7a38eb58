// The registry's GPU claims (vri/methods.hpp gpu_grid, gpu_mesh) are what
// --backend vulkan does: each claimed method renders on the device, the
// others are refused in one line naming the method.
#include <gtest/gtest.h>

#include "methods/method_registry_support.hpp"

namespace vri {
namespace {

TEST(GpuMethods, TheRegistrySaysWhatRunsOnTheGpu) {
  for (const MethodInfo& m : methods())
    for (const bool grid : {true, false}) {
      if (!(grid ? m.grid : m.mesh)) continue;  // the CPU's refusal (tests/methods/)
      const std::string why = test::refusal(test::small_scene(grid, m), Backend::Vulkan);
      if (grid ? m.gpu_grid : m.gpu_mesh)
        EXPECT_EQ(why, "") << m.name << (grid ? " on a grid" : " on a mesh");
      else
        EXPECT_NE(why.find(std::string("method '").append(m.name).append("' ")), std::string::npos) << why;
    }
}

}  // namespace
}  // namespace vri
