#include "tables/cylindrical_table.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vri/error.hpp"
#include "tables/length_table_support.hpp"

namespace vri {
namespace {

const TransferFunction& tf() {
  static const TransferFunction t({{0, 0, 0, 1, 0}, {1, 0, 1, 0, 1.5}, {2, 1, 0.5, 0, 0.2}, {4, 1, 1, 1, 2}});
  return t;
}

// Equation 10 inverts equation 9: a point built on plane alpha maps back to alpha.
TEST(CylindricalTable, AlphaInvertsThePlaneMapping) {
  const LengthTable slab = test::length_table(tf(), 8, 4, 2.0);
  const CylindricalTable cyl(slab, 8, 9);
  for (double a : {0.0, 0.1, 0.25, 0.3, 0.5, 0.6, 0.75, 0.9, 1.0}) {
    const double s = 0.4, t = 0.3;  // normalised plane coordinates
    double sf, l;
    if (a <= 0.25) sf = t + s, l = 4 * a * s;
    else if (a <= 0.5) sf = t + 4 * (0.5 - a) * s, l = s;
    else if (a <= 0.75) sf = t - 4 * (a - 0.5) * s, l = s;
    else sf = t - s, l = 4 * (1 - a) * s;
    // World units: s in [0, 4], lengths up to 2.
    EXPECT_NEAR(cyl.alpha(2 * l, 4 * sf, 4 * t), a, 1e-12) << a;
  }
  EXPECT_EQ(cyl.alpha(0, 1, 1), 0);  // on the diagonal: any plane will do
}

// On a plane's own grid nodes the planes hold the slab table's values.
TEST(CylindricalTable, PlaneNodesHoldTheSlabTable) {
  const LengthTable slab = test::length_table(tf(), 9, 5, 2.0);
  const CylindricalTable cyl(slab, 9, 5);  // planes at alpha = 0, .25, .5, .75, 1
  // Plane alpha = .5 (90 degrees: s_f = s_b = t, l = s): node s = 0.5, t = 0.25.
  const Rgba a = cyl.lookup(0.5, 1.0, 1.0, 1.0), b = slab.lookup(1.0, 1.0, 1.0);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 1e-6);
  EXPECT_GT(b[3], 0.3);
  // Plane alpha = .25 (45 degrees): s_f = t + s, l = s; node s = 0.25, t = 0.5.
  const Rgba c1 = cyl.lookup(0.25, 0.5, 3.0, 2.0), d1 = slab.lookup(0.5, 3.0, 2.0);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(c1[c], d1[c], 1e-6);
}

// Between nodes the resampling costs accuracy; more planes and finer tiles recover it.
TEST(CylindricalTable, ConvergesToTheSlabTable) {
  const LengthTable slab = test::length_table(tf(), 16, 8, 2.0);
  auto max_error = [&](int size, int planes) {
    const CylindricalTable cyl(slab, size, planes);
    double err = 0;
    for (double l : {0.3, 0.9, 1.7})
      for (double sf : {0.2, 1.3, 2.9})
        for (double sb : {0.1, 1.1, 3.7}) {
          const Rgba a = cyl.lookup(cyl.alpha(l, sf, sb), l, sf, sb), b = slab.lookup(l, sf, sb);
          for (int c = 0; c < 4; ++c) err = std::max(err, std::abs(a[c] - b[c]));
        }
    return err;
  };
  const double coarse = max_error(16, 8), fine = max_error(64, 64);
  EXPECT_LT(fine, 0.5 * coarse);
  EXPECT_LT(fine, 0.02);
}

TEST(CylindricalTable, RefusesBadSizes) {
  const LengthTable slab = test::length_table(tf(), 8, 4, 2.0);
  EXPECT_THROW(CylindricalTable(slab, 1, 4), Error);
  EXPECT_THROW(CylindricalTable(slab, 8, 1), Error);
  EXPECT_THROW(CylindricalTable(slab, 4096, 4096), Error);
}

}  // namespace
}  // namespace vri
