// The process's memory account (core/memory_limit.hpp): what MemoryCharges
// hold counts against every later check, so structures that each fit cannot
// together pass the budget; an AccountScope adds a smaller budget on one
// thread; charges made at once on many threads never pass it together.
// Volumes' samples and gradient fields are charged like tables.
#include <gtest/gtest.h>

#include <atomic>
#include <optional>
#include <thread>
#include <vector>

#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/volume.hpp"
#include "volume/gradient_field.hpp"

namespace vri {
namespace {

struct Budget {
  explicit Budget(std::uint64_t bytes) { set_memory_limit(bytes); }
  ~Budget() { set_memory_limit(0); }
};

TEST(MemoryAccount, HeldChargesCountAgainstLaterOnes) {
  const std::uint64_t before = memory_in_use();
  Budget budget(before + (100 << 20));
  MemoryCharge a(60 << 20, "the first table");
  EXPECT_EQ(memory_in_use(), before + (60 << 20));
  try {
    MemoryCharge b(60 << 20, "the second table");
    FAIL() << "two tables of 60 MiB passed a budget of 100 MiB";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the second table would need 60 MiB"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("already held"), std::string::npos) << e.what();
  }
  EXPECT_THROW(check_allocation(60 << 20, "a plain check"), Error);
  EXPECT_EQ(memory_in_use(), before + (60 << 20));  // the refused charge holds nothing
  { MemoryCharge moved = std::move(a); }
  EXPECT_EQ(memory_in_use(), before);
  MemoryCharge c(60 << 20, "the second table, once the first is gone");
  EXPECT_EQ(c.bytes(), std::uint64_t{60} << 20);
}

TEST(MemoryAccount, TablesAndMeshesAreCharged) {
  const std::uint64_t before = memory_in_use();
  {
    ZeroedFloats table(1 << 20);
    EXPECT_EQ(memory_in_use(), before + (4 << 20));
    ZeroedFloats copy = table;
    EXPECT_EQ(memory_in_use(), before + (8 << 20));
  }
  EXPECT_EQ(memory_in_use(), before);
  {
    TetMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 1, 2, 3}}, {0, 1, 2, 3});
    EXPECT_GT(memory_in_use(), before);
  }
  EXPECT_EQ(memory_in_use(), before);
}

TEST(MemoryAccount, VolumesAndGradientsAreChargedOnceForAllTheirCopies) {
  const std::uint64_t before = memory_in_use();
  {
    GridVolume volume({64, 64, 32}, std::vector<float>(64 * 64 * 32, 1.0f));
    EXPECT_EQ(memory_in_use(), before + (512 << 10));
    const GridVolume copy = volume;  // shares the samples
    EXPECT_EQ(memory_in_use(), before + (512 << 10));
    {
      const GradientField gradients(volume);
      EXPECT_EQ(memory_in_use(), before + 4 * (512 << 10));
    }
    // With the volume held, a gradient field that alone fits the budget does not.
    Budget budget(before + (7 << 18));  // 1.75 MiB
    try {
      const GradientField gradients(volume);
      FAIL() << "a 512 KiB volume and its 1.5 MiB gradients passed a 1.75 MiB budget";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("the lighting gradient field"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("512 KiB already held"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(memory_in_use(), before);
  // A volume loaded inside a page's account is the process's (the viewer's
  // catalog shares it between pages), so it outlives the account safely.
  std::optional<GridVolume> shared;
  {
    MemoryAccount page("one page's memory", 1 << 20);
    const AccountScope scope(page);
    shared.emplace(std::array<int, 3>{32, 32, 32}, std::vector<float>(32 * 32 * 32, 1.0f));
    EXPECT_EQ(page.in_use(), 0u);
  }
  EXPECT_EQ(memory_in_use(), before + (128 << 10));
  shared.reset();
  EXPECT_EQ(memory_in_use(), before);
}

TEST(MemoryAccount, AScopedAccountCapsItsThreadAlone) {
  MemoryAccount page("one page's memory", 10 << 20);
  MemoryCharge outside(8 << 20, "outside the page");
  {
    const AccountScope scope(page);
    MemoryCharge first(8 << 20, "a frame");
    EXPECT_EQ(page.in_use(), std::uint64_t{8} << 20);
    try {
      ZeroedFloats table(1 << 20, "a table");
      FAIL() << "12 MiB passed a 10 MiB account";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("over one page's memory of 10 MiB"), std::string::npos) << e.what();
    }
    std::thread other([] { MemoryCharge elsewhere(8 << 20, "on another thread"); });  // not in the scope
    other.join();
  }
  EXPECT_EQ(page.in_use(), 0u);
}

TEST(MemoryAccount, ChargesRacingOnManyThreadsNeverPassTheBudgetTogether) {
  const std::uint64_t before = memory_in_use();
  Budget budget(before + (10 << 20));
  std::atomic<int> held{0}, peak{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&] {
      for (int i = 0; i < 2000; ++i) {
        try {
          MemoryCharge c(1 << 20, "a slice");
          const int now = ++held;
          int p = peak.load();
          while (now > p && !peak.compare_exchange_weak(p, now)) {}
          --held;
        } catch (const Error&) {
        }
      }
    });
  for (auto& t : threads) t.join();
  EXPECT_LE(peak.load(), 10);
  EXPECT_EQ(memory_in_use(), before);
}

}  // namespace
}  // namespace vri
