// libFuzzer harness: tiff (see fuzz_targets.hpp, docs/RELIABILITY.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vri::fuzz::run(vri::fuzz::tiff, data, size);
  return 0;
}
