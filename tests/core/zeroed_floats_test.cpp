#include "vri/memory.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <utility>

#include "vri/error.hpp"

namespace vri {
namespace {

bool all_zero(const ZeroedFloats& f) {
  for (std::size_t i = 0; i < f.size(); ++i)
    if (f[i] != 0.f) return false;
  return true;
}

// Below 1 MiB from the heap (calloc), from 1 MiB up a mapping of whole 2 MiB
// pages: both start at zero, hold what is written, copy and move.
TEST(ZeroedFloats, StartAtZeroOnTheHeapAndOnHugePages) {
  for (std::size_t count : {std::size_t{2}, std::size_t{1000}, std::size_t{(1 << 18) - 1}, std::size_t{1} << 18,
                            std::size_t{512} * 512 * 4 + 3}) {
    ZeroedFloats f(count);
    ASSERT_EQ(f.size(), count);
    EXPECT_TRUE(all_zero(f)) << count;
    if (count * sizeof(float) >= (std::size_t{1} << 20)) {  // mapped: on a 2 MiB boundary, so huge pages can back it
      EXPECT_EQ(reinterpret_cast<std::uintptr_t>(f.data()) % (std::uintptr_t{2} << 20), 0u) << count;
    }
    f[0] = 1.5f;
    f[count - 1] = -2.f;
    const ZeroedFloats copy = f;
    EXPECT_NE(copy.data(), f.data());
    EXPECT_EQ(copy[0], 1.5f);
    EXPECT_EQ(copy[count - 1], -2.f);
    ZeroedFloats moved = std::move(f);
    EXPECT_EQ(f.size(), 0u);  // NOLINT(bugprone-use-after-move): moved-from is empty
    EXPECT_EQ(f.data(), nullptr);
    EXPECT_EQ(moved[count - 1], -2.f);
  }
}

TEST(ZeroedFloats, OverTheMemoryBudgetNamesWhatAndAllocatesNothing) {
  set_memory_limit(std::uint64_t{1} << 20);
  try {
    ZeroedFloats f(std::size_t{1} << 20, "an image");
    ADD_FAILURE() << "4 MiB passed a 1 MiB budget";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("an image of 1048576 floats"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ZeroedFloats(1000).size(), 1000u);  // under the budget
  set_memory_limit(0);
}

}  // namespace
}  // namespace vri
