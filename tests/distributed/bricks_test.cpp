// Sort-last decomposition without MPI: the k-d bricks cover every cell once,
// and every method integrated brick by brick and composited front to back in
// the bricks' BSP order gives the whole volume's pixel (distributed/).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "brick_volume.hpp"
#include "kd_bricks.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"

namespace vri::distributed {
namespace {

TEST(KdBricks, CoverEveryCellOnceInBalancedBricks) {
  const std::array<int, 3> dims{40, 23, 17};
  for (int n = 1; n <= 9; ++n) {
    const KdBricks bricks(dims, n);
    ASSERT_EQ(bricks.count(), n);
    std::vector<int> owners(39 * 22 * 16, 0);
    long long smallest = 1LL << 40, largest = 0;
    for (int b = 0; b < n; ++b) {
      const BrickCells& c = bricks.brick(b);
      const long long cells = 1LL * (c.hi[0] - c.lo[0]) * (c.hi[1] - c.lo[1]) * (c.hi[2] - c.lo[2]);
      smallest = std::min(smallest, cells);
      largest = std::max(largest, cells);
      for (int k = c.lo[2]; k < c.hi[2]; ++k)
        for (int j = c.lo[1]; j < c.hi[1]; ++j)
          for (int i = c.lo[0]; i < c.hi[0]; ++i) ++owners[i + 39 * (j + 22 * k)];
    }
    for (const int o : owners) ASSERT_EQ(o, 1) << n;
    EXPECT_LE(largest, 2 * smallest) << n;  // proportional splits of the longest side
  }
  EXPECT_THROW(KdBricks({3, 3, 3}, 3), Error);  // two cells a side: no third brick
}

// f smooth and not multilinear, on a grid with anisotropic spacing and an
// origin off zero, so cell faces, samples and planes are all inexact doubles.
GridVolume field() {
  return test::volume_from(
      {21, 17, 15},
      [](double x, double y, double z) { return 50 + 40 * std::sin(0.21 * x + 0.1) * std::cos(0.17 * y - 0.3 * z); },
      {0.9, 1.1, 1.3}, {-3.1, 2.2, 0.7});
}

// Opaque enough that order matters, with a spike narrower than a table bin.
const TransferFunction kTf({{10, 0.2, 0.3, 0.9, 0.0},
                            {40, 0.9, 0.4, 0.1, 0.25},
                            {60, 0.3, 1.0, 0.3, 0.05},
                            {60.2, 1.0, 1.0, 1.0, 2.0},
                            {60.4, 0.3, 1.0, 0.3, 0.05},
                            {90, 1.0, 0.2, 0.6, 0.4}});

// A brick takes the whole ray's samples, slabs and cell pieces, and every
// path composites in double (FrontToBack, src/methods/march/ray_steps.hpp): the
// bricks composited give the whole ray to a few double roundings (1e-12;
// float compositing missed 1e-6 on fine steps: 7e-6 on engine, riemann at
// h = 0.05). `guaranteed` takes its own step decisions in each brick: its
// tolerance's share (1e-6 at 1e-4).
struct Case {
  std::string name;
  MethodSpec method;
  bool lit = false;
  double bound = 1e-12;
};

std::vector<Case> cases() {
  const auto m = [](std::string name, double step = 1, bool float_math = true) {
    MethodSpec s;
    s.name = std::move(name);
    s.step = step;
    s.tolerance = 1e-7;
    s.table_size = 128;
    s.fast.float_math = float_math;
    return s;
  };
  MethodSpec jitter = m("riemann", 0.7);
  jitter.jitter = 7;
  MethodSpec guaranteed = m("adaptive");
  guaranteed.strategy = "guaranteed";
  guaranteed.tolerance = 1e-4;
  return {{"exact", m("exact")},
          {"exact_lit", m("exact"), true},
          {"riemann", m("riemann", 0.7)},
          {"riemann_double", m("riemann", 0.45, false)},
          {"riemann_jitter", jitter},
          {"riemann_lit", m("riemann", 0.6), true},
          {"preint1", m("preint1", 0.8)},
          {"preint1_double", m("preint1", 1.3, false)},
          {"preint1_lit", m("preint1", 0.5), true},
          {"preint2", m("preint2", 0.6)},
          {"preint2_double", m("preint2", 0.9, false)},
          {"preint2_dual", m("preint2-dual")},
          {"riemann_fine", m("riemann", 0.02)},
          {"preint1_fine", m("preint1", 0.05)},
          {"adaptive_guaranteed", guaranteed, false, 1e-6}};
}

std::vector<Ray> rays(const GridVolume& v) {
  std::vector<Ray> out;
  const Vec3 centre = 0.5 * (v.box_lo() + v.box_hi());
  for (const CameraSpec& spec :
       {CameraSpec{.eye = {40, 25, 30}, .target = centre, .width = 9, .height = 7},
        CameraSpec{.eye = {-20, 5, -12}, .target = centre, .up = {0, 0, 1}, .width = 9, .height = 7},
        CameraSpec{.eye = centre + Vec3{0.3, -0.2, 0.1}, .target = {30, 30, 30}, .fov_y = 80, .width = 9,
                   .height = 7},  // inside the volume
        CameraSpec{.eye = {5, 30, 8}, .target = centre, .width = 9, .height = 7,
                   .projection = Projection::Orthographic, .ortho_height = 20}}) {
    const Camera camera(spec);
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) out.push_back(camera.ray(x, y));
  }
  return out;
}

TEST(BrickVolume, BricksCompositedFrontToBackGiveTheWholeRay) {
  const GridVolume whole = field();
  const std::vector<Ray> all = rays(whole);
  const CameraSpec views[] = {{.eye = {40, 25, 30}}, {.eye = {-20, 5, -12}}, {.eye = {0, 0, 0}}, {.eye = {5, 30, 8}}};
  for (const Case& c : cases()) {
    Lighting lighting;
    lighting.enabled = c.lit;
    const auto one = make_integrator(c.method, whole, kTf, lighting);
    for (int n : {2, 3, 4, 8}) {
      const KdBricks bricks(whole.dims(), n);
      std::vector<GridVolume> parts;
      std::vector<std::unique_ptr<Integrator>> integrators;
      for (int b = 0; b < n; ++b) parts.push_back(cut_brick(whole, bricks.brick(b), ghost_points(c.method)));
      for (int b = 0; b < n; ++b) integrators.push_back(make_integrator(c.method, parts[b], kTf, lighting));
      // Each brick's rays as the renderer hands them over, a row of 9 at a
      // time (8-ray packets where the build has them, then one alone): the
      // same bytes as ray by ray.
      std::vector<std::vector<Rgba>> rows(n, std::vector<Rgba>(all.size()));
      for (int b = 0; b < n; ++b)
        for (std::size_t r = 0; r < all.size(); r += 9) {
          integrators[b]->integrate_row(all.data() + r, 9, rows[b].data() + r);
          for (std::size_t i = r; i < r + 9; ++i)
            ASSERT_EQ(rows[b][i], integrators[b]->integrate(all[i])) << c.name << " brick " << b << " ray " << i;
        }
      double worst = 0;
      for (std::size_t r = 0; r < all.size(); ++r) {
        // The camera the ray came from: 63 rays each (rays()).
        CameraSpec view = views[r / 63];
        if (r / 63 == 2) view.eye = all[r].origin;
        if (r / 63 == 3) view = {.eye = {5, 30, 8}, .target = 0.5 * (whole.box_lo() + whole.box_hi()),
                                 .projection = Projection::Orthographic, .ortho_height = 20};
        double T = 1, C[3] = {0, 0, 0};
        for (const int b : bricks.front_to_back(view, whole.origin(), whole.spacing())) {
          const Rgba& v = rows[b][r];
          for (int k = 0; k < 3; ++k) C[k] += T * v[k];
          T *= 1 - v[3];
        }
        const Rgba ref = one->integrate(all[r]);
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(C[k] - ref[k]));
        worst = std::max(worst, std::abs((1 - T) - ref[3]));
      }
      EXPECT_LT(worst, c.bound) << c.name << " on " << n << " bricks";
    }
  }
}

// Rays in a split plane belong to one side (the half-open owned box): the
// bricks add up to the whole ray, never twice it.
TEST(BrickVolume, RaysInASplitPlaneHaveOneOwner) {
  const GridVolume whole = field();
  const KdBricks bricks(whole.dims(), 2);
  const int axis = bricks.brick(0).hi[0] != whole.dims()[0] - 1 ? 0 : (bricks.brick(0).hi[1] != whole.dims()[1] - 1 ? 1 : 2);
  const double plane = whole.origin()[axis] + bricks.brick(0).hi[axis] * whole.spacing()[axis];
  MethodSpec exact;
  exact.tolerance = 1e-8;
  const auto one = make_integrator(exact, whole, kTf, {});
  for (const Vec3 dir : {Vec3{0, 0.6, 0.8}, Vec3{0, 0, -1}, Vec3{0.8, 0, 0.6}, Vec3{0.6, 0.8, 0}}) {
    if (dir[axis] != 0) continue;
    Vec3 o = 0.5 * (whole.box_lo() + whole.box_hi()) - 30 * dir;
    o[axis] = plane;
    const Ray ray{o, dir};
    int owners = 0;
    double T = 1, C = 0;
    for (int b = 0; b < 2; ++b) {
      const GridVolume part = cut_brick(whole, bricks.brick(b), 3);
      owners += part.clip(ray).has_value();
      const Rgba v = make_integrator(exact, part, kTf, {})->integrate(ray);
      C += T * v[0];
      T *= 1 - v[3];
    }
    EXPECT_EQ(owners, 1);
    EXPECT_NEAR(C, one->integrate(ray)[0], 1e-7);
  }
}

}  // namespace
}  // namespace vri::distributed
