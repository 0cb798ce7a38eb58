#include "vri/volume/grid_volume.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vri/core/error.hpp"

namespace vri {
namespace {

TEST(GridVolume, TrilinearReproducesTrilinearFields) {
  // a + bx + cy + dz + exy + fxz + gyz + hxyz is reproduced exactly by trilinear interpolation
  auto f = [](double x, double y, double z) {
    return 1 + 0.5 * x - 0.25 * y + 0.125 * z + 0.01 * x * y - 0.02 * x * z + 0.03 * y * z + 0.001 * x * y * z;
  };
  const auto vol = test::volume_from({5, 4, 6}, f, {0.5, 2, 1.5}, {-1, 3, 2});
  for (Vec3 p : {Vec3{-1, 3, 2}, Vec3{0.3, 4.1, 5.5}, Vec3{1, 9, 9.5}, Vec3{0.77, 7.3, 3.21}})
    EXPECT_NEAR(vol.sample(p), f(p.x, p.y, p.z), 1e-5) << p.x << " " << p.y << " " << p.z;
}

TEST(GridVolume, BoxAndVoxelUnit) {
  const auto vol = test::volume_from({5, 4, 6}, [](double, double, double) { return 0; }, {0.5, 2, 1.5}, {-1, 3, 2});
  EXPECT_DOUBLE_EQ(vol.box_hi().x, 1);
  EXPECT_DOUBLE_EQ(vol.box_hi().y, 9);
  EXPECT_DOUBLE_EQ(vol.box_hi().z, 9.5);
  EXPECT_DOUBLE_EQ(vol.voxel_unit(), 0.5);
}

TEST(GridVolume, SamplesOutsideAreClampedToTheBox) {
  const auto vol = test::volume_from({3, 3, 3}, [](double x, double, double) { return x; });
  EXPECT_DOUBLE_EQ(vol.sample({-5, 1, 1}), 0);
  EXPECT_DOUBLE_EQ(vol.sample({9, 1, 1}), 2);
  EXPECT_DOUBLE_EQ(vol.sample({2, 2, 2}), 2);  // the far corner uses the last cell
}

TEST(GridVolume, MinMax) {
  const auto vol = test::volume_from({3, 4, 5}, [](double x, double y, double z) { return x - y * z; });
  EXPECT_FLOAT_EQ(vol.min_value(), -12);
  EXPECT_FLOAT_EQ(vol.max_value(), 2);
}

TEST(GridVolume, RejectsBadConstruction) {
  EXPECT_THROW(GridVolume({1, 4, 4}, std::vector<float>(16)), Error);
  EXPECT_THROW(GridVolume({2, 2, 2}, std::vector<float>(7)), Error);
  std::vector<float> nan(8, 0.f);
  nan[3] = std::nanf("");
  EXPECT_THROW(GridVolume({2, 2, 2}, nan), Error);
  EXPECT_THROW(GridVolume({2, 2, 2}, std::vector<float>(8), {1, 0, 1}), Error);
  EXPECT_THROW(GridVolume::checked_sample_count({100000, 100000, 100000}), Error);
  EXPECT_THROW(GridVolume::checked_sample_count({-3, 10, 10}), Error);
  EXPECT_EQ(GridVolume::checked_sample_count({64, 64, 64}), 262144u);
}

}  // namespace
}  // namespace vri
