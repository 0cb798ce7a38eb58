#include "methods/exact/cubic.hpp"

#include "methods/adaptive/cell_cubics.hpp"

#include <gtest/gtest.h>

#include <random>

#include "test_support.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

// A ray from 15 units away, in a random direction, through a random point
// within 1 of `centre` (inside the volume), and its stretch in the box.
std::pair<Ray, Interval> ray_through(const GridVolume& vol, Vec3 centre, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 target{centre.x + u(rng), centre.y + u(rng), centre.z + u(rng)};
  const Vec3 origin = target - 15 * normalize({u(rng), u(rng), u(rng)});
  const Ray r{origin, normalize(target - origin)};
  const auto iv = clip_to_box(r, vol.box_lo(), vol.box_hi());
  EXPECT_TRUE(iv);
  return {r, iv.value_or(Interval{0, 0})};
}

TEST(Cubic, TrilinearAlongMatchesSamplingInsideEveryCell) {
  const auto vol = random_field({6, 5, 7}, 11);
  std::mt19937 rng(5);
  int checked = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const auto [r, iv] = ray_through(vol, {2.5, 2, 3}, rng);
    for_each_cell_segment(vol, r, iv, [&](const CellSegment& seg) {
      const Cubic s = trilinear_along(vol, seg);
      for (double f : {0.0, 0.3, 0.71, 1.0}) {
        const double t = f * (seg.tb - seg.ta);
        EXPECT_NEAR(s(t), vol.sample(r.at(seg.ta + t)), 1e-6);
        ++checked;
      }
      return true;
    });
  }
  EXPECT_GT(checked, 500);
}

TEST(Cubic, CriticalPointsAndMonotoneRoots) {
  // (t - 1)(t - 2)(t - 4) = t^3 - 7t^2 + 14t - 8; s'(t) = 3t^2 - 14t + 14
  const Cubic s{{-8, 14, -7, 1}};
  double crit[2];
  ASSERT_EQ(s.critical_points(5, crit), 2);
  EXPECT_NEAR(crit[0], (14 - std::sqrt(28.0)) / 6, 1e-14);
  EXPECT_NEAR(crit[1], (14 + std::sqrt(28.0)) / 6, 1e-14);
  EXPECT_EQ(s.critical_points(1, crit), 0);  // both beyond t = 1
  EXPECT_NEAR(s.solve_monotone(0, 0, crit[0] - 1e-3), 1, 1e-14);
  EXPECT_NEAR(s.solve_monotone(0, 3.2, 5), 4, 1e-14);
  EXPECT_NEAR(s.solve_monotone(-0.5, 1.5, 3.2), 2 + 0.0, 0.6);  // lies in the falling run
  const double r = s.solve_monotone(-0.5, (14 - std::sqrt(28.0)) / 6, (14 + std::sqrt(28.0)) / 6);
  EXPECT_NEAR(s(r), -0.5, 1e-13);
  // A straight line has no critical points.
  const Cubic line{{1, 2, 0, 0}};
  EXPECT_EQ(line.critical_points(10, crit), 0);
  EXPECT_NEAR(line.solve_monotone(4, 0, 10), 1.5, 1e-15);
}

// The four-lane cubics of `guaranteed` are trilinear_along's, to the bit,
// for every cell a ray crosses (four at a time, the last group partly
// filled), and their ranges the corners'.
TEST(CellCubics, LanesGiveTheBytesOfTrilinearAlong) {
  const auto vol = random_field({7, 6, 8}, 3);
  std::mt19937 rng(9);
  int checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const auto [r, iv] = ray_through(vol, {3, 2.5, 3.5}, rng);
    std::vector<CellSegment> cells;
    for_each_cell_segment(vol, r, iv, [&](const CellSegment& seg) {
      cells.push_back(seg);
      return true;
    });
    vol.visit([&](auto values) {
      for (std::size_t first = 0; first < cells.size(); first += CellCubics::kLanes) {
        CellCubics cubics;
        const int n = static_cast<int>(std::min<std::size_t>(CellCubics::kLanes, cells.size() - first));
        for (int l = 0; l < n; ++l) cubics.set(l, values.data(), vol, cells[first + l]);
        cubics.run(n);
        for (int l = 0; l < n; ++l) {
          const CellSegment& seg = cells[first + l];
          const Cubic s = trilinear_along(vol, seg);
          for (int j = 0; j < 4; ++j) ASSERT_EQ(cubics.c[j][l], s.c[j]) << trial << " " << l << " " << j;
          const auto& c = seg.cell;
          double lo = INFINITY, hi = -INFINITY;
          for (int k = 0; k < 8; ++k) {
            const double v = vol.at(c[0] + (k & 1), c[1] + (k >> 1 & 1), c[2] + (k >> 2));
            lo = std::min(lo, v), hi = std::max(hi, v);
          }
          ASSERT_EQ(cubics.lo[l], lo);
          ASSERT_EQ(cubics.hi[l], hi);
          ++checked;
        }
      }
    });
  }
  EXPECT_GT(checked, 300);
}

}  // namespace
}  // namespace vri
