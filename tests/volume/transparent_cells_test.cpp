#include "volume/transparent_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "tables/zero_opacity.hpp"
#include "volume/empty_space.hpp"
#include "volume/macro_cells.hpp"

namespace vri {
namespace {

// Zero extinction below 10 and from 30 on.
TransferFunction hat() { return TransferFunction({{10, 1, 1, 1, 0}, {20, 1, 1, 1, 1}, {30, 1, 1, 1, 0}, {40, 1, 1, 1, 0}}); }

// Every cell of a non-empty macro cell is marked exactly when the cell test
// of the guaranteed walk (its corners' range +- margin on ZeroOpacityBins)
// passes, every other cell is clear: on odd sizes (partial macro cells, rows
// and planes that end inside a 64-bit word), in bytes and in floats.
TEST(TransparentCells, MarksExactlyTheCellsWhoseRangeHasNoExtinction) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  // Mostly 0 (transparent) with blobs reaching into the hat: some macro cells empty, some not.
  const auto field = [&](double x, double y, double z) {
    const double d = std::hypot(x - 20, y - 9, z - 12);
    return std::clamp(40 - 4 * d + 6 * u(rng), 0.0, 255.0);
  };
  const GridVolume floats = test::volume_from({37, 29, 23}, field);
  std::vector<std::uint8_t> bytes;
  for (float v : test::floats(floats)) bytes.push_back(static_cast<std::uint8_t>(v));
  const GridVolume u8({37, 29, 23}, GridVolume::Samples(std::move(bytes)));
  const TransferFunction tf = hat();
  const ZeroOpacity zero(tf);  // (keeps a reference to tf)
  for (const GridVolume* volume : {&floats, &u8}) {
    const MacroCells cells(*volume);
    const EmptySpace space(cells, zero);
    ASSERT_GT(space.empty_count(), 0u);
    ASSERT_LT(space.empty_count(), cells.count());
    const double margin = interpolation_margin(*volume);
    const ZeroOpacityBins bins(zero, volume->min_value() - margin, volume->max_value() + margin);
    const TransparentCells transparent(*volume, space, bins, margin);
    const auto& n = volume->dims();
    std::size_t marked = 0, tested = 0;
    for (int k = 0; k + 1 < n[2]; ++k)
      for (int j = 0; j + 1 < n[1]; ++j)
        for (int i = 0; i + 1 < n[0]; ++i) {
          const int K = MacroCells::kCells;
          bool want = false;
          if (!space.empty(cells.index(i / K, j / K, k / K))) {
            std::array<float, 8> c{};
            for (int q = 0; q < 8; ++q) c[q] = volume->at(i + (q & 1), j + (q >> 1 & 1), k + (q >> 2));
            const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
            want = bins.over(*lo - margin, *hi + margin);
            ++tested;
          }
          ASSERT_EQ(transparent.transparent(i, j, k), want) << i << " " << j << " " << k;
          marked += want;
        }
    EXPECT_EQ(transparent.count(), marked);
    EXPECT_GT(marked, tested / 10);  // both kinds occur among the cells tested
    EXPECT_LT(marked, tested * 9 / 10);
  }
}

// The bits are checked against the memory budget (--max-memory) before they
// are allocated, as every structure sized by the volume is.
TEST(TransparentCells, RefusesToExceedTheMemoryBudget) {
  const GridVolume volume = test::volume_from({64, 64, 64}, [](double x, double, double) { return x; });
  const TransferFunction tf = hat();
  const ZeroOpacity zero(tf);
  const MacroCells cells(volume);
  const EmptySpace space(cells, zero);
  const ZeroOpacityBins bins(zero, volume.min_value(), volume.max_value());
  set_memory_limit(16 * 1024);  // the bits take 32 KiB
  try {
    TransparentCells transparent(volume, space, bins, 0);
    set_memory_limit(0);
    FAIL() << "no error";
  } catch (const Error& e) {
    set_memory_limit(0);
    EXPECT_NE(std::string(e.what()).find("transparent-cell bits"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(TransparentCells(volume, space, bins, 0));
}

}  // namespace
}  // namespace vri
