#include "methods/exact/mesh_exact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>

#include "mesh/mesh_test_support.hpp"
#include "vri/error.hpp"
#include "methods/exact/exact.hpp"
#include "vri/render.hpp"

namespace vri {
namespace {

double linear(double x, double y, double z) { return 0.3 * x - 0.2 * y + 0.45 * z + 1; }

// Max over pixels and channels of |a - b| on an n x n view of the linear
// field's box; alpha_sum gets the sum of a's alpha.
double max_diff_on_view(const Integrator& a, const Integrator& b, int n, double& alpha_sum) {
  CameraSpec cs;
  cs.eye = {9, -7, 12};
  cs.target = {0.5, 3, 3.5};
  cs.width = cs.height = n;
  const Camera cam(cs);
  double max_diff = 0;
  alpha_sum = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Ray r = cam.ray(x, y);
      const Rgba u = a.integrate(r), v = b.integrate(r);
      alpha_sum += u[3];
      for (int c = 0; c < 4; ++c) max_diff = std::max(max_diff, std::abs(u[c] - v[c]));
    }
  return max_diff;
}

// A field linear in space is the same field on the grid (trilinear) and on its
// tetrahedra (piecewise linear), so `exact` must agree on every ray.
TEST(MeshExact, LinearFieldMatchesTheGridRender) {
  std::mt19937 rng(11);
  const GridVolume grid = test::volume_from({6, 5, 7}, linear, {1, 1.5, 0.75}, {-2, 0, 1});
  for (int per_cell : {5, 6}) {
    const TetMesh mesh = tetrahedralize(grid, per_cell);
    for (int trial = 0; trial < 4; ++trial) {
      const TransferFunction tf = test::random_tf(rng, 4, 0.8);
      const ExactIntegrator on_grid(grid, tf, 1e-9);
      const MeshExactIntegrator on_mesh(mesh, tf, 1e-9);
      double alpha_sum;
      EXPECT_LT(max_diff_on_view(on_grid, on_mesh, 24, alpha_sum), 1e-7) << "per_cell " << per_cell << " trial " << trial;
      EXPECT_GT(alpha_sum, 20) << "the view must hit the volume";
    }
  }
}

TEST(MeshExact, GapsHoldNothing) {
  // Two unit-thick slabs 2 apart, constant tau: alpha = 1 - exp(-tau (1 + 1)).
  const TetMesh m = test::carved_mesh(5, [](double, double, double) { return 1.0; },
                                      [](double x, double, double) { return x < 1 || x > 3; });
  const TransferFunction tf({{0, 0.5, 0.25, 1, 0.6}});
  const MeshExactIntegrator ex(m, tf, 1e-10);
  const Rgba c = ex.integrate({{-1, 2.2, 1.7}, {1, 0, 0}});
  const double alpha = 1 - std::exp(-0.6 * 2);
  EXPECT_NEAR(c[3], alpha, 1e-12);
  EXPECT_NEAR(c[0], 0.5 * alpha, 1e-9);
  EXPECT_NEAR(c[2], alpha, 1e-9);
}

TEST(MeshExact, SameBytesWithAnyThreadCount) {
  const TetMesh m = test::carved_mesh(6, linear, [](double x, double y, double) { return x < 2 || y > 3; });
  const TransferFunction tf({{0, 0, 0, 1, 0}, {2, 1, 0.5, 0, 0.4}, {4, 1, 1, 1, 0.1}});
  for (const Lighting& light : {Lighting{}, Lighting{true, 0.3, 0.7, 0.4, 32, "sampled"}}) {
    const MeshExactIntegrator ex(m, tf, 1e-6, light);
    CameraSpec cs;
    cs.eye = {-6, -5, 9};
    cs.target = {2.5, 2.5, 2.5};
    cs.width = 33;
    cs.height = 29;
    const Camera cam(cs);
    const Image one = render(cam, ex, {.threads = 1});
    const Image two = render(cam, ex, {.threads = 2, .tile_size = 5});
    ASSERT_EQ(0, std::memcmp(one.data().data(), two.data().data(), one.data().size() * sizeof(float)));
  }
}

// Lit (SPEC §5): on a linear field the grid's central differences and the
// mesh's point gradients are both the field's gradient, so lit exact agrees
// on grid and mesh too.
TEST(MeshExact, LitLinearFieldMatchesLitGridExact) {
  std::mt19937 rng(13);
  const GridVolume grid = test::volume_from({6, 5, 7}, linear, {1, 1.5, 0.75}, {-2, 0, 1});
  const Lighting light{true, 0.2, 0.6, 0.8, 16, "sampled"};
  for (int per_cell : {5, 6}) {
    const TetMesh mesh = tetrahedralize(grid, per_cell);
    const TransferFunction tf = test::random_tf(rng, 4, 0.8);
    const ExactIntegrator on_grid(grid, tf, 1e-9, light), unlit(grid, tf, 1e-9);
    const MeshExactIntegrator on_mesh(mesh, tf, 1e-9, light);
    double alpha_sum;
    EXPECT_LT(max_diff_on_view(on_grid, on_mesh, 16, alpha_sum), 1e-5) << "per_cell " << per_cell;
    EXPECT_GT(max_diff_on_view(on_grid, unlit, 16, alpha_sum), 0.05) << "the lighting must show";
  }
}

double wave(double x, double y, double z) { return 0.5 + 0.4 * std::sin(0.9 * x + 0.5 * y) * std::cos(0.7 * z); }

TEST(MeshExact, LitHonoursItsTolerance) {
  // A curved field: the normal turns inside each tetrahedron and N.d changes sign.
  const TetMesh m = test::carved_mesh(6, wave, [](double x, double y, double) { return x < 2 || y > 3; });
  const TransferFunction tf({{0, 0, 0, 1, 0}, {0.3, 0, 1, 0, 0.2}, {0.6, 1, 1, 0, 1.2}, {1, 1, 0, 0, 0.4}});
  const Lighting light{true, 0.3, 0.7, 0.4, 32, "sampled"};
  const MeshExactIntegrator ex(m, tf, 1e-5, light), tight(m, tf, 1e-10, light);
  CameraSpec cs;
  cs.eye = {-6, -5, 9};
  cs.target = {2.5, 2.5, 2.5};
  cs.width = cs.height = 20;
  const Camera cam(cs);
  double max_diff = 0;
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      const Rgba a = ex.integrate(cam.ray(x, y)), b = tight.integrate(cam.ray(x, y));
      for (int c = 0; c < 4; ++c) max_diff = std::max(max_diff, std::abs(a[c] - b[c]));
    }
  EXPECT_LT(max_diff, 1e-5);
}

TEST(MeshExact, RefusesBadTolerance) {
  const TetMesh m = test::unit_tet();
  const TransferFunction tf({{0, 1, 1, 1, 1}});
  EXPECT_THROW(MeshExactIntegrator(m, tf, 0), Error);
  EXPECT_THROW(MeshExactIntegrator(m, tf, 1), Error);
}

}  // namespace
}  // namespace vri
