// ZeroSpots (tables/zero_spots.hpp): a spot is zero exactly when the eight
// entries a trilinear blend there reads are zero in every table, checked
// against the entries themselves on sparse random tables.
#include "tables/zero_spots.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace vri {
namespace {

constexpr int kN = 7;
std::size_t index(int f, int m, int b) { return (static_cast<std::size_t>(f) * kN + m) * kN + b; }

TEST(ZeroSpots, AreTheSpotsWhoseEightEntriesAreZeroInEveryTable) {
  std::mt19937 rng(3);
  std::bernoulli_distribution nonzero(0.02);
  std::uniform_int_distribution<int> channel(0, 3);
  std::vector<std::vector<float>> tables(3, std::vector<float>(4 * kN * kN * kN, 0.0f));
  for (auto& t : tables)
    for (std::size_t e = 0; e < index(kN - 1, kN - 1, kN - 1) + 1; ++e)
      if (nonzero(rng)) t[4 * e + channel(rng)] = 1e-30f;  // tiny, not zero
  tables[1][4 * index(1, 1, 1) + 2] = -0.0f;  // negative zero is zero
  const ZeroSpots spots(kN, {tables[0].data(), tables[1].data(), tables[2].data()});
  int zeros = 0, others = 0;
  for (int f = 0; f < kN; ++f)
    for (int m = 0; m < kN; ++m)
      for (int b = 0; b < kN; ++b) {
        bool want = f < kN - 1 && m < kN - 1 && b < kN - 1;  // spots on an upper face are never looked up
        for (int c = 0; c < 8 && want; ++c)
          for (const auto& t : tables)
            for (int k = 0; k < 4; ++k)
              if (t[4 * index(f + (c & 1), m + (c >> 1 & 1), b + (c >> 2)) + k] != 0) want = false;
        EXPECT_EQ(spots.zero(index(f, m, b)), want) << f << " " << m << " " << b;
        (want ? zeros : others)++;
      }
  EXPECT_GT(zeros, 20);  // both kinds occur
  EXPECT_GT(others, 20);
}

TEST(ZeroSpots, OneNonZeroEntryClearsTheEightSpotsThatReadIt) {
  std::vector<float> table(4 * kN * kN * kN, 0.0f);
  table[4 * index(3, 2, 4) + 3] = 0.5f;
  const ZeroSpots spots(kN, {table.data()});
  for (int f = 0; f + 1 < kN; ++f)
    for (int m = 0; m + 1 < kN; ++m)
      for (int b = 0; b + 1 < kN; ++b) {
        const bool reads = (f == 3 || f == 2) && (m == 2 || m == 1) && (b == 4 || b == 3);
        EXPECT_EQ(spots.zero(index(f, m, b)), !reads);
      }
}

}  // namespace
}  // namespace vri
