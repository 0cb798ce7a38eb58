// The Vulkan tests run with the Khronos validation layer on (the device reads
// VRI_VULKAN_VALIDATION when it is first made) and count its messages: none
// may appear (issue 22, item 5). Set before any test makes the device.
#include <cstdlib>

namespace {
const bool kValidationOn = setenv("VRI_VULKAN_VALIDATION", "1", /*overwrite=*/0) == 0;
}  // namespace
