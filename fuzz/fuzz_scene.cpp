// libFuzzer harness: scene (see fuzz_targets.hpp, docs/RELIABILITY.md).
#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vri::fuzz::run(vri::fuzz::scene, data, size);
  return 0;
}
