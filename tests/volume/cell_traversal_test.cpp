#include "volume/cell_traversal.hpp"

#include <gtest/gtest.h>

#include <random>

#include "test_support.hpp"

namespace vri {
namespace {

struct Walk {
  std::vector<CellSegment> segs;
};

Walk walk(const GridVolume& vol, const Ray& ray) {
  Walk w;
  const auto iv = clip_to_box(ray, vol.box_lo(), vol.box_hi());
  if (iv) for_each_cell_segment(vol, ray, *iv, [&](const CellSegment& s) { w.segs.push_back(s); return true; });
  return w;
}

TEST(CellTraversal, AxisAlignedRayVisitsEveryCellOnce) {
  const auto vol = test::volume_from({9, 5, 5}, [](double, double, double) { return 0; });
  const auto w = walk(vol, {{-2, 1.5, 2.5}, {1, 0, 0}});
  ASSERT_EQ(w.segs.size(), 8u);
  for (int i = 0; i < 8; ++i) {
    EXPECT_EQ(w.segs[i].cell[0], i);
    EXPECT_EQ(w.segs[i].cell[1], 1);
    EXPECT_EQ(w.segs[i].cell[2], 2);
    EXPECT_NEAR(w.segs[i].tb - w.segs[i].ta, 1.0, 1e-12);
  }
}

TEST(CellTraversal, SegmentsTileTheChordAndStayInTheirCells) {
  const auto vol = test::volume_from({7, 6, 5}, [](double, double, double) { return 0; }, {0.7, 1.3, 0.9}, {1, -2, 0.5});
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 target{1 + 4.2 * (u(rng) + 1) / 2, -2 + 6.5 * (u(rng) + 1) / 2, 0.5 + 3.6 * (u(rng) + 1) / 2};
    const Vec3 eye = target - 20 * normalize({u(rng), u(rng), u(rng)});
    const Ray ray{eye, normalize(target - eye)};
    const auto iv = clip_to_box(ray, vol.box_lo(), vol.box_hi());
    ASSERT_TRUE(iv);
    const auto w = walk(vol, ray);
    ASSERT_FALSE(w.segs.empty());
    EXPECT_DOUBLE_EQ(w.segs.front().ta, iv->t0);
    EXPECT_DOUBLE_EQ(w.segs.back().tb, iv->t1);
    for (std::size_t i = 0; i < w.segs.size(); ++i) {
      const auto& s = w.segs[i];
      if (i) {
        EXPECT_DOUBLE_EQ(s.ta, w.segs[i - 1].tb);
      }
      for (int a = 0; a < 3; ++a) {
        const double enter = s.local0[a], leave = s.local0[a] + s.local_dir[a] * (s.tb - s.ta);
        EXPECT_GE(std::min(enter, leave), -1e-9);
        EXPECT_LE(std::max(enter, leave), 1 + 1e-9);
      }
    }
  }
}

TEST(CellTraversal, RayAlongTheFarFaceUsesTheLastCell) {
  const auto vol = test::volume_from({4, 4, 4}, [](double, double, double) { return 0; });
  const auto w = walk(vol, {{-1, 3, 3}, {1, 0, 0}});
  ASSERT_EQ(w.segs.size(), 3u);
  EXPECT_EQ(w.segs[0].cell[1], 2);
  EXPECT_NEAR(w.segs[0].local0.y, 1, 1e-12);
}

}  // namespace
}  // namespace vri
