#include "mesh/tetrahedralize.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"

namespace vri {
namespace {

class Tetrahedralize : public ::testing::TestWithParam<int> {};

TEST_P(Tetrahedralize, FillsTheBoxConformingly) {
  const int per_cell = GetParam();
  const GridVolume g = test::volume_from({4, 3, 5}, [](double x, double y, double z) { return x + 2 * y - z; },
                                         {0.5, 1, 2}, {1, 2, 3});
  const TetMesh m = tetrahedralize(g, per_cell);
  EXPECT_EQ(m.size(), std::size_t(3 * 2 * 4 * per_cell));
  EXPECT_EQ(m.dropped(), 0u);
  double volume = 0;
  for (const auto& t : m.tets()) {
    const auto& p = m.points();
    volume += dot(p[t[1]] - p[t[0]], cross(p[t[2]] - p[t[0]], p[t[3]] - p[t[0]])) / 6;
  }
  EXPECT_NEAR(volume, 1.5 * 2 * 8, 1e-12);
  // Conforming: the only boundary faces are the two triangles of each cell
  // face on the box surface (a mismatched diagonal would add more).
  std::size_t boundary = 0;
  for (std::size_t t = 0; t < m.size(); ++t)
    for (int f = 0; f < 4; ++f) boundary += m.neighbor(t, f) < 0;
  EXPECT_EQ(boundary, std::size_t(2 * 2 * (3 * 2 + 2 * 4 + 3 * 4)));
  EXPECT_EQ(m.box_lo().y, 2);
  EXPECT_EQ(m.box_hi().z, 11);
}

INSTANTIATE_TEST_SUITE_P(PerCell, Tetrahedralize, ::testing::Values(5, 6));

TEST(TetrahedralizeErrors, RefusesOtherSplits) {
  const GridVolume g = test::volume_from({2, 2, 2}, [](double, double, double) { return 0.0; });
  EXPECT_THROW(tetrahedralize(g, 4), Error);
}

// The memory budget (--max-memory) is consulted before the mesh is built.
TEST(TetrahedralizeErrors, RespectsTheMemoryLimit) {
  const GridVolume g = test::volume_from({4, 4, 4}, [](double x, double, double) { return x; });
  set_memory_limit(2000);  // 64 points (1536 bytes) + 135 tetrahedra (2160 bytes)
  EXPECT_THROW(tetrahedralize(g, 5), Error);
  set_memory_limit(0);
  EXPECT_EQ(tetrahedralize(g, 5).size(), 135u);
}

}  // namespace
}  // namespace vri
