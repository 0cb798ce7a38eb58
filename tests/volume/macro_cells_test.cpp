#include "volume/macro_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <tbb/parallel_for.h>

#include "tables/random_tf.hpp"
#include "test_support.hpp"
#include "tables/second_order_table.hpp"
#include "tables/zero_opacity.hpp"
#include "volume/empty_space.hpp"

namespace vri {
namespace {

// Every macro cell's range is the min and max over its corner points 8I .. 8I + 8,
// by brute force.
void expect_brute_force_ranges(const GridVolume& volume) {
  const MacroCells cells(volume);
  const auto& n = volume.dims();
  for (int a = 0; a < 3; ++a) ASSERT_EQ(cells.dims()[a], (n[a] - 2) / 8 + 1);
  for (int K = 0; K < cells.dims()[2]; ++K)
    for (int J = 0; J < cells.dims()[1]; ++J)
      for (int I = 0; I < cells.dims()[0]; ++I) {
        float lo = 1e9f, hi = -1e9f;
        for (int k = 8 * K; k <= std::min(n[2] - 1, 8 * K + 8); ++k)
          for (int j = 8 * J; j <= std::min(n[1] - 1, 8 * J + 8); ++j)
            for (int i = 8 * I; i <= std::min(n[0] - 1, 8 * I + 8); ++i) {
              lo = std::min(lo, volume.at(i, j, k));
              hi = std::max(hi, volume.at(i, j, k));
            }
        ASSERT_EQ(cells.min(cells.index(I, J, K)), lo) << I << " " << J << " " << K;
        ASSERT_EQ(cells.max(cells.index(I, J, K)), hi) << I << " " << J << " " << K;
      }
}

// On dims that are not multiples of 8, and that are (one point more than a
// multiple: the last macro cell is one cell thin).
TEST(MacroCells, RangesAreTheMinMaxOfTheirPoints) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5, 5);
  const GridVolume volume = test::volume_from({19, 9, 26}, [&](double, double, double) { return u(rng); });
  EXPECT_EQ(MacroCells(volume).dims(), (std::array<int, 3>{3, 1, 4}));
  expect_brute_force_ranges(volume);
  expect_brute_force_ranges(test::volume_from({17, 25, 10}, [&](double, double, double) { return u(rng); }));
}

// The same on each storage type, random samples over its whole range.
template <class T>
GridVolume random_volume(std::array<int, 3> dims, int lo, int hi, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> u(lo, hi);
  std::vector<T> v(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);
  for (T& x : v) x = static_cast<T>(u(rng));
  return GridVolume(dims, std::move(v));
}

TEST(MacroCells, RangesOnEachStorageType) {
  expect_brute_force_ranges(random_volume<std::uint8_t>({21, 18, 30}, 0, 255, 1));
  expect_brute_force_ranges(random_volume<std::uint16_t>({9, 33, 17}, 0, 65535, 2));
  expect_brute_force_ranges(random_volume<std::int16_t>({26, 11, 41}, -32768, 32767, 3));
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

// The binned test never calls a range empty that ZeroOpacity does not, and
// still finds the wide empty runs: random spiky transfer functions, random
// ranges inside and across the span, and ranges outside it (false).
TEST(ZeroOpacityBins, ConservativeAgainstZeroOpacityAndFindsTheEmptyRuns) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const TransferFunction tf = test::random_spiky_tf(seed, 5);
    const ZeroOpacity zero(tf);
    const ZeroOpacityBins bins(zero, 0, 255, 512);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 255), w(0, 3);
    int found = 0, empty = 0;
    for (int k = 0; k < 20000; ++k) {
      const double a = u(rng), b = std::min(255.0, a + w(rng));
      const bool exact = zero.over(a, b), binned = bins.over(a, b);
      ASSERT_FALSE(binned && !exact) << seed << ": [" << a << ", " << b << "]";
      empty += exact;
      found += binned;
    }
    // Bins are 0.5 wide: all but the ranges within about a bin of a control
    // point of a zero-opacity run's ends are found.
    EXPECT_GT(found, 0.8 * empty) << seed;
    EXPECT_FALSE(bins.over(-1, 3));
    EXPECT_FALSE(bins.over(250, 256));
  }
  const ZeroOpacityBins bins(ZeroOpacity(hat()), 0, 100, 1000);
  EXPECT_TRUE(bins.over(0, 9.8));
  EXPECT_FALSE(bins.over(9.8, 10.05));
  EXPECT_TRUE(bins.over(30.2, 100));
}

// Table scalars x_i = i, i = 0 .. 100; tau = 0 exactly for i = 10 .. 90.
DiscreteTf gap() {
  return DiscreteTf(TransferFunction({{0, 1, 1, 1, 1}, {9, 1, 1, 1, 1}, {10, 1, 1, 1, 0}, {90, 1, 1, 1, 0},
                                      {91, 1, 1, 1, 1}, {100, 1, 1, 1, 1}}),
                    101);
}

// A second-order entry's parabola leaves the range of its three scalars by
// up to 1/8 of it: scalars in 10..90 are not enough, only those at least
// 80/8 = 10 inside the run are (21..79 here), and there every entry is 0.
TEST(ZeroOpacity, SecondOrderEntriesStayInsideTheRunTheyAreClassifiedIn) {
  const DiscreteTf tf = gap();
  const ZeroOpacity first(tf), second(tf, TableOrder::Second);
  EXPECT_TRUE(first.over(10, 90));
  EXPECT_FALSE(second.over(10, 90));
  EXPECT_TRUE(second.over(21, 79));
  EXPECT_FALSE(second.over(20, 79));
  EXPECT_FALSE(second.over(21, 80));
  EXPECT_FALSE(second.over(20.5, 79));  // reads the entry at 20
  // the parabola through 20, 90, 90 peaks at 90 + 70/8 = 98.75, where tau = 1
  EXPECT_GT(second_order_entry(tf, 20, 90, 90, 1.0, 64).a, 0);
  for (int f = 21; f <= 79; f += 2)
    for (int m = 21; m <= 79; ++m)
      for (int b = 21; b <= 79; b += 3) {
        const SlabRgba e = second_order_entry(tf, f, m, b, 1.0, 32);
        ASSERT_TRUE(e.r == 0 && e.g == 0 && e.b == 0 && e.a == 0) << f << " " << m << " " << b;
      }
  for (const auto& builder : {"plain", "fast"}) {
    const SecondOrderTable table = make_second_order_builder(builder)->build(tf, 1.0, 32);
    for (int f = 21; f <= 79; ++f)
      for (int m = 21; m <= 79; ++m)
        for (int b = 21; b <= 79; ++b)
          for (int c = 0; c < 4; ++c) ASSERT_EQ(table.entry(f, m, b)[c], 0.0f) << builder << f << " " << m << " " << b;
  }
}

// At an end of the axis the parabola is clamped, so only the other end of the
// run needs the margin: tau = 0 on 0..50 of 0..100 allows scalars 0..43.
TEST(ZeroOpacity, SecondOrderNeedsNoMarginAtTheEndsOfTheAxis) {
  const DiscreteTf tf(TransferFunction({{0, 1, 1, 1, 0}, {50, 1, 1, 1, 0}, {51, 1, 1, 1, 1}, {100, 1, 1, 1, 1}}), 101);
  const ZeroOpacity second(tf, TableOrder::Second);
  EXPECT_TRUE(second.over(-5, 43));
  EXPECT_FALSE(second.over(-5, 44));
  for (int f = 0; f <= 43; ++f)
    for (int b = 0; b <= 43; ++b) EXPECT_EQ(second_order_entry(tf, f, 0, b, 1.0, 32).a, 0) << f << " " << b;
}

// A bin with extinction inside (a split bin) ends a run of zero tau, but its
// table scalars stay in the runs on either side when their own tau is 0: here
// tau = 0 on [0, 50.5] and on [10.5, 89.5] of table scalars 0..100, so the
// runs are the table scalars 0..50 and 11..89, (b - a)/8 of which leaves
// 0..43 and 21..79, and every entry over them is 0 with the plain and the
// fast builder (the fast one reads first-order entries at the table scalars
// around each chord end, so a run cannot end inside a bin). Counting a split bin's table
// scalars as opaque gave 0..42 and 22..78; on fuel's 64-entry table, whose
// zero run ends at 10 in the bin 8.1..12.1, not one macro cell (issue 21).
TEST(ZeroOpacity, SecondOrderRunsKeepTheZeroTableScalarsOfASplitBin) {
  const DiscreteTf end(
      TransferFunction({{0, 1, 1, 1, 0}, {50.5, 1, 1, 1, 0}, {51.5, 1, 1, 1, 1}, {100, 1, 1, 1, 1}}), 101);
  const DiscreteTf inner(TransferFunction({{0, 1, 1, 1, 1}, {9.5, 1, 1, 1, 1}, {10.5, 1, 1, 1, 0}, {89.5, 1, 1, 1, 0},
                                          {90.5, 1, 1, 1, 1}, {100, 1, 1, 1, 1}}),
                         101);
  const ZeroOpacity zero_end(end, TableOrder::Second), zero_inner(inner, TableOrder::Second);
  EXPECT_TRUE(zero_end.over(-5, 43));
  EXPECT_FALSE(zero_end.over(-5, 43.01));
  EXPECT_TRUE(zero_inner.over(21, 79));
  EXPECT_FALSE(zero_inner.over(20.99, 79));
  EXPECT_FALSE(zero_inner.over(21, 79.01));
  // Scalars near a run's end are not enough: 0, 45, 45 peaks at 45 + 45/8 = 50.6.
  EXPECT_GT(second_order_entry(end, 0, 45, 45, 1.0, 64).a, 0);
  for (const auto& builder : {"plain", "fast"}) {
    const SecondOrderTable te = make_second_order_builder(builder)->build(end, 1.0, 16);
    const SecondOrderTable ti = make_second_order_builder(builder)->build(inner, 1.0, 16);
    for (int f = 0; f <= 79; ++f)
      for (int m = 0; m <= 79; ++m)
        for (int b = 0; b <= 79; ++b)
          for (int c = 0; c < 4; ++c) {
            if (f <= 43 && m <= 43 && b <= 43) {
              ASSERT_EQ(te.entry(f, m, b)[c], 0.0f) << builder << f << " " << m << " " << b;
            }
            if (f >= 21 && m >= 21 && b >= 21) {
              ASSERT_EQ(ti.entry(f, m, b)[c], 0.0f) << builder << f << " " << m << " " << b;
            }
          }
  }
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
  EmptySpace::Walk walk(space, ray, 1, 33);
  EmptySpace::Run a, b, c, after;
  ASSERT_TRUE(walk.next(a) && walk.next(b) && walk.next(c));
  EXPECT_FALSE(walk.next(after));
  EXPECT_TRUE(a.empty);
  EXPECT_DOUBLE_EQ(a.t_end, 17);
  EXPECT_FALSE(b.empty);
  EXPECT_DOUBLE_EQ(b.t_end, 25);
  EXPECT_TRUE(c.empty);
  EXPECT_DOUBLE_EQ(c.t_end, 33);

  const GridVolume two = test::volume_from({33, 33, 33}, [](double x, double y, double z) {
    return (x == 20 || x == 28) && y == 20 && z == 20 ? 50.0 : 0.0;
  });
  const MacroCells cells2(two);
  const EmptySpace space2(cells2, ZeroOpacity(tf));
  EmptySpace::Walk from_inside(space2, ray, 18, 40);
  EmptySpace::Run d;
  ASSERT_TRUE(from_inside.next(d));
  EXPECT_FALSE(d.empty);
  EXPECT_DOUBLE_EQ(d.t_end, 40);  // leaves the macro grid at x = 32 (t = 33) still non-empty: t_max
  EXPECT_FALSE(from_inside.next(d));
}

// occupied_box holds every non-empty macro cell and occupied_parts covers
// each of them, inside the box, with boxes that hold no more than runs of
// non-empty cells along x (or, past 4096 macro cells, of blocks of 2 a
// side): scattered points on grids of 5^3 to 40^3 macro cells, uneven
// spacing and origin. (The renderer casts no ray that misses the parts.)
TEST(EmptySpace, OccupiedPartsCoverEveryNonEmptyCellAndLittleElse) {
  const TransferFunction tf = hat();
  std::mt19937 rng(5);
  for (const int n : {33, 41, 100, 321}) {
    std::uniform_int_distribution<int> at(0, n - 1);
    std::vector<std::array<int, 3>> points(6);
    for (auto& p : points) p = {at(rng), at(rng), at(rng) % 40};
    const GridVolume volume = test::volume_from(
        {n, n, 40},
        [&](double x, double y, double z) {  // world positions: back to grid points
          const std::array<long, 3> g{std::lround((x + 3) / 0.5), std::lround((y - 7) / 1.25),
                                      std::lround((z - 1) / 2)};
          for (const auto& p : points)
            if (g[0] == p[0] && g[1] == p[1] && g[2] == p[2]) return 50.0;
          return 0.0;
        },
        {0.5, 1.25, 2}, {-3, 7, 1});
    const MacroCells cells(volume);
    const EmptySpace space(cells, ZeroOpacity(tf));
    const Box box = space.occupied_box();
    const std::vector<Box> parts = space.occupied_parts();
    const auto& m = cells.dims();
    const bool blocks = std::size_t(m[0]) * m[1] * m[2] > 4096;
    const auto inside = [](const Box& in, const Box& out) {
      for (int a = 0; a < 3; ++a)
        if (in.lo[a] < out.lo[a] || in.hi[a] > out.hi[a]) return false;
      return true;
    };
    double part_volume = 0;
    for (const Box& part : parts) {
      EXPECT_TRUE(inside(part, box)) << n;
      part_volume += (part.hi.x - part.lo.x) * (part.hi.y - part.lo.y) * (part.hi.z - part.lo.z);
    }
    int non_empty = 0;
    for (int k = 0; k < m[2]; ++k)
      for (int j = 0; j < m[1]; ++j)
        for (int i = 0; i < m[0]; ++i) {
          if (space.empty(cells.index(i, j, k))) continue;
          ++non_empty;
          Box cell;  // the macro cell's box, within the volume's
          const std::array<int, 3> c{i, j, k};
          for (int a = 0; a < 3; ++a) {
            const double side = MacroCells::kCells * volume.spacing()[a];
            cell.lo[a] = std::min(volume.origin()[a] + c[a] * side, volume.whole_hi()[a]);
            cell.hi[a] = std::min(volume.origin()[a] + (c[a] + 1) * side, volume.whole_hi()[a]);
          }
          EXPECT_TRUE(inside(cell, box)) << n << " cell " << i << " " << j << " " << k;
          EXPECT_TRUE(std::any_of(parts.begin(), parts.end(), [&](const Box& p) { return inside(cell, p); }))
              << n << " cell " << i << " " << j << " " << k;
        }
    ASSERT_GT(non_empty, 0);
    // The parts hold the non-empty cells' volume, a little more where cells
    // are merged into blocks; far less than the box.
    const double cell_volume = 512 * volume.spacing().x * volume.spacing().y * volume.spacing().z;
    EXPECT_LE(part_volume, non_empty * cell_volume * (blocks ? 8 : 1) + 1e-9) << n;
  }
}

// for_each_occupied_run hands out the non-empty runs in order, and they and
// the leaps between them partition the interval: the ray x = -1 + t meets
// macro cells 0..4 along x; with points at x = 20 and 28, cells 2 and 3
// (x 16..32, t 17..33) hold them and are walked, the rest leapt over.
TEST(EmptySpace, OccupiedRunsPartitionTheRay) {
  const TransferFunction tf = hat();
  const Ray ray{{-1, 20, 20}, {1, 0, 0}};
  // The parts of [1, 41] on a 41 x 33 x 33 grid with points of 50 at x = xs, y = z = 20.
  const auto parts_with_points_at = [&](std::vector<double> xs) {
    const GridVolume volume = test::volume_from({41, 33, 33}, [&](double x, double y, double z) {
      return std::count(xs.begin(), xs.end(), x) && y == 20 && z == 20 ? 50.0 : 0.0;
    });
    const MacroCells cells(volume);
    const EmptySpace space(cells, ZeroOpacity(tf));
    std::vector<std::pair<double, double>> parts;
    for_each_occupied_run(&space, ray, Interval{1, 41}, [&](const Interval& part) {
      parts.emplace_back(part.t0, part.t1);
      return true;
    });
    return parts;
  };
  using Parts = std::vector<std::pair<double, double>>;
  EXPECT_EQ(parts_with_points_at({20, 28}), (Parts{{17, 33}}));
  // x = 20 and x = 36 lie in macro cells 2 (points 16..24, t 17..25) and 4
  // (points 32..40, t 33..41); cell 3 between them is leapt over.
  EXPECT_EQ(parts_with_points_at({20, 36}), (Parts{{17, 25}, {33, 41}}));
  // The visit may stop the walk; without a space the whole interval is one part.
  int calls = 0;
  for_each_occupied_run(nullptr, ray, Interval{1, 41}, [&](const Interval& part) {
    EXPECT_EQ(part.t0, 1);
    EXPECT_EQ(part.t1, 41);
    return ++calls < 0;
  });
  EXPECT_EQ(calls, 1);
}

// One walk hands out the runs: on sparse random data, rays started on macro
// cell faces and grid lines (where rounding puts a point on either side) have
// their parts cover exactly the points whose macro cell is non-empty. A walk
// that located each run's first cell afresh could land back in the empty
// cell it had just left, find a run of no length there and give up, handing
// out the rest of the ray (empty cells too) as one part.
TEST(EmptySpace, OccupiedRunsCoverExactlyTheNonEmptyCells) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  const GridVolume volume =
      test::volume_from({41, 41, 41}, [&](double, double, double) { return u(rng) < 4e-4 ? 15.0 : 0.0; });
  const MacroCells cells(volume);
  const EmptySpace space(cells, ZeroOpacity(hat()));
  ASSERT_GT(space.empty_count(), cells.count() / 4);
  ASSERT_LT(space.empty_count(), cells.count() * 3 / 4);
  const auto cell_empty = [&](Vec3 p) {
    int m[3];
    for (int a = 0; a < 3; ++a) m[a] = std::min(static_cast<int>(std::clamp(p[a], 0.0, 40.0)), 39) / MacroCells::kCells;
    return space.empty(cells.index(m[0], m[1], m[2]));
  };
  int parts_seen = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Ray ray = test::ray_along_faces(rng, trial);
    const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
    if (!iv) continue;
    std::vector<Interval> parts;
    for_each_occupied_run(&space, ray, *iv, [&](const Interval& part) {
      parts.push_back(part);
      return true;
    });
    parts_seen += static_cast<int>(parts.size());
    for (int k = 0; k <= 200; ++k) {
      const double t = iv->t0 + (iv->t1 - iv->t0) * (k + 0.37) / 201;
      bool inside = false, near_end = false;
      for (const Interval& part : parts) {
        inside = inside || (t > part.t0 && t < part.t1);
        near_end = near_end || std::abs(t - part.t0) < 1e-6 || std::abs(t - part.t1) < 1e-6;
      }
      if (!near_end) {
        ASSERT_EQ(inside, !cell_empty(ray.at(t))) << "trial " << trial << " t " << t;
      }
    }
  }
  EXPECT_GT(parts_seen, 200);
}

// A walk's runs, as the marches ask for them (MacroRuns): every point of an
// empty run lies in an empty macro cell (the one the sampler reads there),
// and the runs end at the ray's exit, on a volume whose non-empty cells
// fill a box inside air, so that most of each ray lies before or after that
// box, and on rays along faces and grid lines.
TEST(EmptySpace, EmptyRunsHoldOnlyEmptyCells) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  const std::array<int, 3> n = {49, 41, 33};
  const GridVolume volume = test::volume_from(n, [&](double x, double y, double z) {
    const bool inside = x > 17 && x < 31 && y > 9 && y < 23 && z > 8 && z < 21;
    return inside && u(rng) < 2e-3 ? 15.0 : 0.0;
  });
  const MacroCells cells(volume);
  const TransferFunction tf = hat();
  const EmptySpace space(cells, ZeroOpacity(tf));
  ASSERT_LT(space.empty_count(), cells.count());
  const auto cell_empty = [&](Vec3 p) {
    int m[3];
    for (int a = 0; a < 3; ++a)
      m[a] = std::min(static_cast<int>(std::clamp(p[a], 0.0, n[a] - 1.0)), n[a] - 2) / MacroCells::kCells;
    return space.empty(cells.index(m[0], m[1], m[2]));
  };
  int nonempty_runs = 0, empty_points = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const Ray ray = trial % 2 ? test::ray_along_faces(rng, trial / 2)
                              : Ray{{u(rng) * 48, u(rng) * 40, -5}, normalize(Vec3{u(rng) - 0.5, u(rng) - 0.5, 1})};
    const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
    if (!iv) continue;
    double t = iv->t0;
    EmptySpace::Walk walk(space, ray, t, iv->t1);
    EmptySpace::Run run;
    for (int guard = 0; walk.next(run); ++guard) {
      ASSERT_LT(guard, 1000);
      ASSERT_LE(run.t_end, iv->t1);
      ASSERT_GE(run.t_end, t);
      if (run.empty) {
        for (int k = 0; k <= 50; ++k) {
          const double x = t + (run.t_end - t) * (k + 0.5) / 51;
          if (x - t > 1e-6 && run.t_end - x > 1e-6) {
            ASSERT_TRUE(cell_empty(ray.at(x))) << "trial " << trial << " t " << x;
            ++empty_points;
          }
        }
      } else {
        ++nonempty_runs;
      }
      t = run.t_end;
    }
    EXPECT_EQ(t, iv->t1);
  }
  EXPECT_GT(nonempty_runs, 50);
  EXPECT_GT(empty_points, 10000);
}

// The ranges are computed once per volume and shared by its copies (a
// transfer-function edit makes a new integrator, not new ranges); concurrent
// first uses agree on one computation; another volume gets its own.
TEST(MacroCells, RangesAreComputedOncePerVolumeAndSharedByCopies) {
  const GridVolume volume = test::volume_from({40, 30, 20}, [](double x, double y, double z) { return x * y - z; });
  std::vector<const MacroRanges*> seen(64);
  tbb::parallel_for(0, 64, [&](int i) { seen[i] = &volume.macro_ranges(); });
  for (const MacroRanges* p : seen) EXPECT_EQ(p, seen[0]);
  GridVolume copy = volume;
  copy.set_spacing({2, 2, 2});  // ranges are in sample space: still the same
  EXPECT_EQ(&copy.macro_ranges(), seen[0]);
  const MacroRanges fresh = compute_macro_ranges(volume);
  EXPECT_EQ(fresh.lo, volume.macro_ranges().lo);
  EXPECT_EQ(fresh.hi, volume.macro_ranges().hi);
  const GridVolume other = test::volume_from({40, 30, 20}, [](double x, double y, double z) { return x * y - z; });
  EXPECT_NE(&other.macro_ranges(), seen[0]);
  EXPECT_EQ(MacroCells(other).min(5), MacroCells(volume).min(5));
}

}  // namespace
}  // namespace vri
