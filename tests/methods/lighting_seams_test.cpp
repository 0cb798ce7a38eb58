// No seams at slab boundaries (issue 16, item 6): a lit pre-integrated image
// must be a continuous function of the ray. Slab boundaries move with the
// ray's entry point and the number of slabs changes where the chord length
// passes a multiple of the step; a seam is a jump there - a slab's lit colour
// that does not meet its neighbour's, a partial last slab dropped or counted
// twice. The test sweeps a family of parallel rays across a lit field that is
// translucent (the last slab of a ray still shows, T ~ 0.1 there) and non-empty
// everywhere (boundary slabs included), and compares the largest
// jump between neighbouring rays at two spacings: a continuous result's jumps
// shrink with the spacing (about 4x for 4x finer), a seam's do not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "test_support.hpp"
#include "vri/methods.hpp"

namespace vri {
namespace {

GridVolume lit_field() {
  return test::volume_from({24, 24, 24}, [](double x, double y, double z) {
    return 20 + 1.75 * (x + y + z) + 10 * std::sin(0.3 * x) * std::cos(0.2 * y);
  });
}

TransferFunction smooth_tf() {
  return TransferFunction({{0, 0, 0, 0, 0.02},
                           {60, 1, 0.5, 0.2, 0.08},
                           {100, 0.2, 0.8, 0.4, 0.03},
                           {160, 0.3, 0.3, 1, 0.12}});
}

// n parallel rays, direction d, through the volume's centre offset by
// x0 + i * dx along a direction perpendicular to d.
std::vector<Ray> sweep(double x0, double dx, int n) {
  const Vec3 d = normalize(Vec3{1, 0.37, 0.23});
  const Vec3 side = normalize(cross(d, Vec3{0, 0, 1}));
  const Vec3 centre{11.5, 11.5, 11.5};
  std::vector<Ray> rays(n);
  for (int i = 0; i < n; ++i) rays[i] = {centre - 100.0 * d + (x0 + i * dx) * side, d};
  return rays;
}

// The largest change of any channel between neighbouring rays.
double largest_jump(const Integrator& method, const std::vector<Ray>& rays, bool rows) {
  std::vector<Rgba> out(rays.size());
  if (rows) {
    method.integrate_row(rays.data(), int(rays.size()), out.data());
  } else {
    for (std::size_t i = 0; i < rays.size(); ++i) out[i] = method.integrate(rays[i]);
  }
  double jump = 0;
  for (std::size_t i = 1; i < out.size(); ++i)
    for (int c = 0; c < 4; ++c) jump = std::max(jump, std::abs(double(out[i][c]) - double(out[i - 1][c])));
  return jump;
}

TEST(LightingSeams, LitSlabsMeetAtTheirBoundaries) {
  const GridVolume volume = lit_field();
  const TransferFunction tf = smooth_tf();
  // 12 voxels across the field: chords of 14 to 40 voxels, so the step of 1.3
  // leaves partial last slabs and the slab count changes many times.
  const std::vector<Ray> coarse = sweep(-6, 0.01, 1201), fine = sweep(-6, 0.0025, 4801);
  MethodSpec exact{.name = "exact", .tolerance = 1e-8};
  const Lighting lit{true, 0.3, 0.7, 0.4, 32, "sampled"};
  const double exact_coarse = largest_jump(*make_integrator(exact, volume, tf, lit), coarse, false);
  for (const char* mode : {"interpolated", "sampled"}) {
    const Lighting lighting{true, 0.3, 0.7, 0.4, 32, mode};
    for (const char* name : {"preint1", "preint2"}) {
      MethodSpec spec{.name = name, .step = 1.3};
      if (std::string(name) == "preint2") spec.table_size = 64, spec.table_size_given = true;
      const auto method = make_integrator(spec, volume, tf, lighting);
      for (bool rows : {false, true}) {
        const double j_coarse = largest_jump(*method, coarse, rows), j_fine = largest_jump(*method, fine, rows);
        std::printf("%s %s %s: largest jump %.3g at spacing 0.01, %.3g at 0.0025 (lit exact %.3g)\n", name, mode,
                    rows ? "rows" : "rays", j_coarse, j_fine, exact_coarse);
        EXPECT_GT(j_coarse, 0) << "the sweep must see the field";
        EXPECT_LT(j_fine, 0.4 * j_coarse) << name << " " << mode << (rows ? " rows" : " rays");
      }
    }
  }
}

}  // namespace
}  // namespace vri
