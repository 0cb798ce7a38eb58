#include "tables/preintegration_table.hpp"

#include <gtest/gtest.h>

namespace vri {
namespace {

// Entries hold r = f, g = b (the indices), so bilinear lookups are exact planes.
PreintegrationTable index_table() {
  PreintegrationTable t(ScalarAxis{10, 20, 11}, 1.0);
  for (int f = 0; f < 11; ++f)
    for (int b = 0; b < 11; ++b) {
      t.entry(f, b)[0] = float(f);
      t.entry(f, b)[1] = float(b);
      t.entry(f, b)[2] = float(f * b);
    }
  return t;
}

TEST(PreintegrationTable, LookupInterpolatesBilinearly) {
  const PreintegrationTable t = index_table();
  const Rgba v = t.lookup(13.25, 17.5);
  EXPECT_DOUBLE_EQ(v[0], 3.25);
  EXPECT_DOUBLE_EQ(v[1], 7.5);
  // f*b is bilinear inside a cell: 0.25 * 0.5 * (4*8) + ... exactly 3.25 * 7.5.
  EXPECT_DOUBLE_EQ(v[2], 3.25 * 7.5);
}

TEST(PreintegrationTable, EndEntriesHoldOutsideTheAxis) {
  const PreintegrationTable t = index_table();
  EXPECT_DOUBLE_EQ(t.lookup(-5, 25)[0], 0);
  EXPECT_DOUBLE_EQ(t.lookup(-5, 25)[1], 10);
  EXPECT_DOUBLE_EQ(t.lookup(20, 20)[2], 100);
}

TEST(ScalarAxis, MapsScalarsToIndices) {
  const ScalarAxis axis{-1, 3, 5};
  EXPECT_DOUBLE_EQ(axis.scalar(4), 3);
  EXPECT_DOUBLE_EQ(axis.index(0.5), 1.5);
  EXPECT_DOUBLE_EQ(axis.index(7), 4);
  EXPECT_DOUBLE_EQ((ScalarAxis{2, 2, 5}.index(9)), 0);
}

}  // namespace
}  // namespace vri
