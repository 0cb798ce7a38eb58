#include "vri/volume/macro_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "test_support.hpp"
#include "vri/tables/zero_opacity.hpp"
#include "vri/volume/empty_space.hpp"

namespace vri {
namespace {

// Every macro cell's range is the min and max over its corner points 8I .. 8I + 8,
// by brute force, on dims that are not multiples of 8.
TEST(MacroCells, RangesAreTheMinMaxOfTheirPoints) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  const GridVolume volume = test::volume_from({19, 9, 26}, [&](double, double, double) { return u(rng); });
  const MacroCells cells(volume);
  ASSERT_EQ(cells.dims(), (std::array<int, 3>{3, 1, 4}));
  for (int K = 0; K < 4; ++K)
    for (int J = 0; J < 1; ++J)
      for (int I = 0; I < 3; ++I) {
        float lo = 1e9f, hi = -1e9f;
        for (int k = 8 * K; k <= std::min(25, 8 * K + 8); ++k)
          for (int j = 8 * J; j <= std::min(8, 8 * J + 8); ++j)
            for (int i = 8 * I; i <= std::min(18, 8 * I + 8); ++i) {
              lo = std::min(lo, volume.at(i, j, k));
              hi = std::max(hi, volume.at(i, j, k));
            }
        EXPECT_EQ(cells.min(cells.index(I, J, K)), lo) << I << J << K;
        EXPECT_EQ(cells.max(cells.index(I, J, K)), hi) << I << J << K;
      }
}

// tau: 0 below 10, up to 1 at 20, down to 0 at 30, 0 above.
TransferFunction hat() { return TransferFunction({{10, 1, 1, 1, 0}, {20, 1, 1, 1, 1}, {30, 1, 1, 1, 0}, {40, 1, 1, 1, 0}}); }

TEST(ZeroOpacity, FollowsTheTransferFunctionPieces) {
  const TransferFunction tf = hat();
  const ZeroOpacity zero(tf);
  EXPECT_TRUE(zero.over(-5, 9.9));
  EXPECT_FALSE(zero.over(-5, 10));  // the piece [10, 20) rises: conservative at its zero end
  EXPECT_FALSE(zero.over(25, 35));
  EXPECT_TRUE(zero.over(30, 1e9));
}

TEST(ZeroOpacity, FollowsTheEntriesABilinearLookupReads) {
  const DiscreteTf tf(hat(), 4);  // entries at 10, 20, 30, 40 with tau 0, 1, 0, 0
  const ZeroOpacity zero(tf);
  EXPECT_TRUE(zero.over(-5, 10));   // a lookup at 10 gives the entry at 20 weight 0
  EXPECT_FALSE(zero.over(-5, 15));  // the lookup at 15 reads the entry at 20
  EXPECT_TRUE(zero.over(30, 100));
  EXPECT_FALSE(zero.over(25, 35));
}

// One non-zero sample at (20, 20, 20), in macro cell (2, 2, 2) only: a ray
// along x at y = z = 20 leaps to x = 16, then stays in that cell until x = 24.
// Another non-zero sample at (28, 20, 20) makes (3, 2, 2) non-empty too: the
// non-empty run then lasts until x = 32, the far face.
TEST(EmptySpace, RunsEndAtTheFacesOfNonEmptyCells) {
  const GridVolume volume = test::volume_from(
      {33, 33, 33}, [](double x, double y, double z) { return x == 20 && y == 20 && z == 20 ? 50.0 : 0.0; });
  const MacroCells cells(volume);
  const TransferFunction tf = hat();
  const EmptySpace space(cells, ZeroOpacity(tf));
  EXPECT_EQ(space.empty_count(), cells.count() - 1);
  const Ray ray{{-1, 20, 20}, {1, 0, 0}};
  const EmptySpace::Run a = space.run(ray, 1, 33);
  EXPECT_TRUE(a.empty);
  EXPECT_DOUBLE_EQ(a.t_end, 17);
  const EmptySpace::Run b = space.run(ray, 18, 33);
  EXPECT_FALSE(b.empty);
  EXPECT_DOUBLE_EQ(b.t_end, 25);
  const EmptySpace::Run c = space.run(ray, 26, 33);
  EXPECT_TRUE(c.empty);
  EXPECT_DOUBLE_EQ(c.t_end, 33);

  const GridVolume two = test::volume_from({33, 33, 33}, [](double x, double y, double z) {
    return (x == 20 || x == 28) && y == 20 && z == 20 ? 50.0 : 0.0;
  });
  const MacroCells cells2(two);
  const EmptySpace space2(cells2, ZeroOpacity(tf));
  const EmptySpace::Run d = space2.run(ray, 18, 40);
  EXPECT_FALSE(d.empty);
  EXPECT_DOUBLE_EQ(d.t_end, 40);  // leaves the macro grid at x = 32 (t = 33) still non-empty: t_max
}

}  // namespace
}  // namespace vri
