// libFuzzer harness: npy_volume (see fuzz_targets.hpp, docs/RELIABILITY.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vri::fuzz::run(vri::fuzz::npy_volume, data, size);
  return 0;
}
