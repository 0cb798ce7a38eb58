// DualFloatLookup (src/methods/preint2_dual/dual_march.hpp): preint2-dual's
// (l, s_f, s_m, s_b) table read in float, the two length slices blended
// first, then s_m, s_f and s_b. Quadrilinear interpolation reproduces any
// function that is linear in each index separately, whatever the order of
// its blends: on such a table the lookup is the function itself at the
// continuous indices, up to float roundings, in every table it reads.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "methods/preint2_dual/dual_march.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/second_order_table.hpp"
#include "tables/zero_opacity.hpp"
#include "vri/transfer_function.hpp"

namespace vri {
namespace {

constexpr int kN = 9, kLengths = 5;
constexpr double kMaxLength = 2;

// Channel c of a multilinear function of the continuous indices (length
// slice, front, middle, back), between 0.05 and 1.
double multilinear(int c, int table, double l, double f, double m, double b) {
  const double k = 1 + 0.5 * table + 0.25 * c;
  return 0.05 + 0.01 * k * (2 * l + f + 3 * m + b) + 2e-4 * k * l * f * m * b - 1e-3 * f * b + 5e-4 * l * m;
}

SecondOrderLengthTable filled(int table) {
  const ScalarAxis axis{0, kN - 1, kN};  // index = scalar
  std::vector<SecondOrderTable> slices;
  for (int i = 0; i < kLengths; ++i) {
    SecondOrderTable slice(axis, kMaxLength * i / (kLengths - 1), 1);
    for (int f = 0; f < kN; ++f)
      for (int m = 0; m < kN; ++m)
        for (int b = 0; b < kN; ++b)
          for (int c = 0; c < 4; ++c) slice.entry(f, m, b)[c] = static_cast<float>(multilinear(c, table, i, f, m, b));
    slices.push_back(std::move(slice));
  }
  return SecondOrderLengthTable(std::move(slices), kMaxLength);
}

TEST(DualFloatLookup, ReproducesMultilinearTablesInEveryTable) {
  const SecondOrderLengthTable full = filled(0), middle = filled(1), back = filled(2);
  const detail::DualFloatLookup lookup(full, &middle, &back);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> length(0, kMaxLength), scalar(0, kN - 1);
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const double l = length(rng);
    const std::array<float, 3> s = {static_cast<float>(scalar(rng)), static_cast<float>(scalar(rng)),
                                    static_cast<float>(scalar(rng))};
    const auto spot = lookup.find(l, s[0], s[1], s[2]);
    // The slice index as length_bracket computes it, in float as the spot keeps it.
    const double u = spot.i + static_cast<double>(spot.wl);
    EXPECT_NEAR(u, l / kMaxLength * (kLengths - 1), 1e-6);
    for (int table = 0; table < 3; ++table) {
      const Float4 v = lookup.blend(spot, table);
      for (int c = 0; c < 4; ++c) {
        const double want = multilinear(c, table, u, s[0], s[1], s[2]);
        worst = std::max(worst, std::abs(v[c] - want));
        ASSERT_NEAR(v[c], want, 2e-6) << "table " << table << " channel " << c << " at l " << l;
      }
    }
    // The double lookup, which blends in another order, agrees.
    const Rgba d = full.lookup(l, s[0], s[1], s[2]);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(lookup.blend(spot)[c], d[c], 2e-6);
  }
  EXPECT_GT(worst, 0);  // float roundings, not a lookup that reads the entries exactly
}

// Ends of the axes: a length at or past max_length reads the last two
// slices with all weight on the last; scalars past the axis clamp to its
// ends, as the double lookup does.
TEST(DualFloatLookup, ClampsAtTheEndsOfItsAxes) {
  const SecondOrderLengthTable full = filled(0);
  const detail::DualFloatLookup lookup(full);
  for (const double l : {kMaxLength, 3 * kMaxLength}) {
    const auto spot = lookup.find(l, -4.0f, 20.0f, 8.0f);
    EXPECT_EQ(spot.i, kLengths - 2);
    EXPECT_EQ(spot.wl, 1.0f);
    const Float4 v = lookup.blend(spot);
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(v[c], multilinear(c, 0, kLengths - 1, 0, kN - 1, kN - 1), 1e-6);
  }
  const auto zero_length = lookup.find(0, 1.5f, 2.5f, 3.5f);
  EXPECT_EQ(zero_length.i, 0);
  EXPECT_EQ(zero_length.wl, 0.0f);
  EXPECT_NEAR(lookup.blend(zero_length)[3], multilinear(3, 0, 0, 1.5, 2.5, 3.5), 1e-6);
}

// Spots of zeros (ZeroSpots) are not read: zero entries where f <= 3 and
// b <= 4 in every slice of the full table, except one entry of the middle
// table. A spot whose eight entries are zero in both slices of all three
// tables gives +0, bit for bit what blending the zeros gives; every other
// spot still blends its entries (the weighted tables' one entry shows).
TEST(DualFloatLookup, SpotsOfZerosGivePlusZeroAndOnlyThey) {
  const auto zeroed = [](int table) {
    SecondOrderLengthTable t = filled(table);
    std::vector<SecondOrderTable> slices;
    for (int i = 0; i < kLengths; ++i) {
      SecondOrderTable slice = t.slices()[i];
      for (int f = 0; f <= 3; ++f)
        for (int m = 0; m < kN; ++m)
          for (int b = 0; b <= 4; ++b)
            for (int c = 0; c < 4; ++c) slice.entry(f, m, b)[c] = table == 1 && i == 2 && f == 1 && m == 5 && b == 2 ? 0.25f : 0.0f;
      slices.push_back(std::move(slice));
    }
    return SecondOrderLengthTable(std::move(slices), kMaxLength);
  };
  const SecondOrderLengthTable full = zeroed(0), middle = zeroed(1), back = zeroed(2);
  const detail::DualFloatLookup lit(full, &middle, &back), unlit(full);
  int skipped = 0, read = 0;
  for (int f = 0; f + 1 < kN; ++f)
    for (int m = 0; m + 1 < kN; ++m)
      for (int b = 0; b + 1 < kN; ++b)
        for (const double l : {0.3, 1.1}) {
          const float s[3] = {f + 0.375f, m + 0.5f, b + 0.625f};
          const bool zero_entries = f + 1 <= 3 && b + 1 <= 4;
          const bool middle_one = (f == 1 || f == 0) && (m == 5 || m == 4) && (b == 2 || b == 1);
          const auto a = unlit.find(l, s[0], s[1], s[2]);
          EXPECT_EQ(unlit.zero(a.at), zero_entries);
          const auto spot = lit.find(l, s[0], s[1], s[2]);
          EXPECT_EQ(lit.zero(spot.at), zero_entries && !middle_one);
          for (int table = 0; table < 3; ++table) {
            const Float4 v = lit.blend(spot, table);
            const Rgba d = (table == 0 ? full : table == 1 ? middle : back).lookup(l, s[0], s[1], s[2]);
            for (int c = 0; c < 4; ++c) {
              if (lit.zero(spot.at)) {
                EXPECT_EQ(std::bit_cast<std::uint32_t>(v[c]), 0u);  // +0, not -0
              } else {
                EXPECT_NEAR(v[c], d[c], 2e-6);
              }
            }
          }
          if (middle_one && zero_entries && l > 1) {
            EXPECT_GT(lit.blend(spot, 1)[0], 0);  // read, not skipped
          }
          (lit.zero(spot.at) ? skipped : read)++;
        }
  EXPECT_GT(skipped, 50);
  EXPECT_GT(read, 50);
}

// What the float path's transparent cells rely on (preint2_dual.cpp): a
// cell whose corners' range, widened by the rounding margin, lies where
// ZeroOpacityBins over a second-order ZeroOpacity sees no extinction gives
// samples whose every lookup reads zero entries, whatever three samples of
// that range a segment takes (the parabola through them leaves the range by
// up to an eighth of its width). Transfer function: zero up to 100, then a
// steep opaque ramp. The same ranges classified for first-order entries let
// some segment read a non-zero entry: what the second-order margin is for.
TEST(DualFloatLookup, TransparentRangesOfSecondOrderEntriesReadOnlyZeros) {
  const TransferFunction tf({{0, 1, 1, 1, 0}, {100, 1, 1, 1, 0}, {104, 1, 0.5, 0.2, 40}, {255, 1, 1, 1, 40}});
  const DiscreteTf d(tf, 32);
  const SecondOrderLengthTable table =
      build_second_order_length_table(*make_second_order_builder("fast"), d, 4, kMaxLength, 8);
  const detail::DualFloatLookup lookup(table);
  const double margin = 1e-5 * 510;  // interpolation_margin of a 0..255 volume
  const ZeroOpacity second(d, TableOrder::Second), first(d, TableOrder::First);
  const ZeroOpacityBins second_bins(second, -margin, 255 + margin), first_bins(first, -margin, 255 + margin);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0, 1);
  int ranges = 0, first_only_nonzero = 0;
  for (int k = 0; k < 20000; ++k) {
    const float lo = static_cast<float>(120 * unit(rng)), hi = std::min(255.0f, lo + static_cast<float>(60 * unit(rng)));
    const bool zero2 = second_bins.over(lo - margin, hi + margin), zero1 = first_bins.over(lo - margin, hi + margin);
    if (!zero1 && !zero2) continue;
    ASSERT_TRUE(zero1) << "second-order zero implies first-order zero";
    const float mid = 0.5f * (lo + hi);
    bool nonzero = false;
    for (const std::array<float, 3> s : {std::array{lo, hi, hi}, std::array{hi, hi, lo}, std::array{lo, mid, hi},
                                         std::array{hi, lo, lo}, std::array{lo, lo, lo}, std::array{hi, hi, hi}})
      for (const double l : {0.4, 1.0, kMaxLength}) {
        const Float4 v = lookup.blend(lookup.find(l, s[0], s[1], s[2]));
        for (int c = 0; c < 4; ++c) {
          if (zero2) {
            ASSERT_EQ(std::bit_cast<std::uint32_t>(v[c]), 0u) << lo << " .. " << hi;
          }
          nonzero = nonzero || v[c] != 0;
        }
      }
    ranges += zero2;
    first_only_nonzero += !zero2 && nonzero;
  }
  EXPECT_GT(ranges, 1000);
  EXPECT_GT(first_only_nonzero, 0);
}

}  // namespace
}  // namespace vri
