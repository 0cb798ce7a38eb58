// Every input the fuzz harnesses (fuzz/) ever crashed, hung or ran out of
// memory on, kept under tests/data/fuzz/<harness>/ and replayed through the
// same entry: each must now end in vri::Error or succeed (ASan/UBSan builds
// check the memory safety).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz_targets.hpp"
#include "test_support.hpp"

namespace vri {
namespace {

TEST(FuzzRegressions, EveryKeptInputIsHandled) {
  const std::filesystem::path root = test::source_path("tests/data/fuzz");
  std::size_t replayed = 0;
  for (const auto& [name, target] : fuzz::targets()) {
    if (!std::filesystem::is_directory(root / name)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(root / name)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      SCOPED_TRACE(entry.path().string());
      EXPECT_NO_THROW(fuzz::run(target, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
      ++replayed;
    }
  }
  EXPECT_GT(replayed, 0u);
  set_memory_limit(0);
}

}  // namespace
}  // namespace vri
