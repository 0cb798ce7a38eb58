// Clipping (SPEC §12 "clip", issue 50; docs/CLIPPING.md) on every method
// and path: each integrates the kept part of the ray to the cut exactly.
//  - A transfer function of one colour and one extinction gives every
//    method, table and step the closed form c (1 - exp(-tau L)), L the
//    length of the ray the region keeps, found here by bisection on the
//    region's definition (n . p + d >= 0, inside the box and the volume).
//  - A crop box equal to a sub-volume's box renders, with `exact`, what the
//    sub-volume renders as its own volume (issue 50's metamorphic test).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "mesh/mesh_test_support.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

constexpr double kTau = 3.0;
constexpr double kColour[3] = {0.8, 0.4, 0.2};

// One colour and one extinction over the field's whole range [0, 4].
TransferFunction flat_tf() {
  return TransferFunction({{0, kColour[0], kColour[1], kColour[2], kTau}, {4, kColour[0], kColour[1], kColour[2], kTau}});
}

// x + 2y + z on [0, 1]^3: a field that is not constant (so tables and
// steps are exercised) in [0, 4].
GridVolume unit_grid() {
  return test::volume_from({9, 9, 9}, [](double x, double y, double z) { return x + 2 * y + z; }, {0.125, 0.125, 0.125});
}

// An oblique plane through the box and a crop box that cuts it on every
// axis, away from the grid's points and the steps' ends.
ClipRegion oblique_cut() {
  return {{{{0.3, -0.2, 1.0}, -0.41}, {{-1.0, 0.15, 0.05}, 0.83}}, Box{{0.07, 0.11, -1}, {0.93, 0.87, 0.777}}};
}

CameraSpec view(int width = 23, int height = 19) {
  CameraSpec c;
  c.eye = {2.3, 1.7, 2.9};
  c.target = {0.5, 0.45, 0.5};
  c.up = {0, 0, 1};
  c.fov_y = 38;
  c.width = width;
  c.height = height;
  return c;
}

// The length of the ray inside `lo`..`hi` and the region, the test's own
// way: every constraint (the two boxes' faces too) a half-space a . p + b
// >= 0, the kept part of the ray the intersection of their half-lines; its
// ends checked against the region's definition (n . p + d >= 0, inside
// the boxes) just inside and just outside.
double kept_length(const Ray& ray, const ClipRegion& region, Vec3 lo, Vec3 hi) {
  std::vector<ClipPlane> half_spaces = region.planes;
  const auto box_faces = [&](Vec3 a, Vec3 b) {
    for (int axis = 0; axis < 3; ++axis) {
      Vec3 n{0, 0, 0};
      n[axis] = 1;
      half_spaces.push_back({n, -a[axis]});  // p >= a
      half_spaces.push_back({-1 * n, b[axis]});  // p <= b
    }
  };
  box_faces(lo, hi);
  if (region.box) box_faces(region.box->lo, region.box->hi);
  double t0 = 0, t1 = 1e300;
  for (const ClipPlane& h : half_spaces) {
    const double along = dot(h.normal, ray.dir), height = dot(h.normal, ray.origin) + h.d;
    if (along == 0) {
      if (height < 0) return 0;
      continue;
    }
    if (along > 0) t0 = std::max(t0, -height / along);
    if (along < 0) t1 = std::min(t1, -height / along);
  }
  if (!(t1 > t0)) return 0;
  const auto kept = [&](double t) {
    const Vec3 p = ray.at(t);
    for (const ClipPlane& h : half_spaces)
      if (dot(h.normal, p) + h.d < -1e-12) return false;
    return true;
  };
  const double e = 1e-9 * (1 + t1);
  EXPECT_TRUE(kept(0.5 * (t0 + t1)) && (t1 - t0 < 4 * e || (kept(t0 + e) && kept(t1 - e))));
  EXPECT_FALSE(kept(t1 + 1e-6) || (t0 > 0 && kept(t0 - 1e-6)));
  return t1 - t0;
}

std::vector<std::string> grid_methods() {
  std::vector<std::string> names;
  for (const MethodInfo& m : methods())
    if (m.grid && m.per_ray) names.emplace_back(m.name);
  return names;
}

struct ClipCase {
  std::string method;
  bool float_math;
};

class ClipEveryGridMethod : public ::testing::TestWithParam<ClipCase> {};

TEST_P(ClipEveryGridMethod, IntegratesToTheCutExactly) {
  const ClipCase& c = GetParam();
  Scene scene{unit_grid(), flat_tf(), view(), Lighting{}, {0, 0, 0}, MethodSpec{}};
  scene.method.name = c.method;
  scene.method.fast.float_math = c.float_math;
  scene.method.step = 0.37;  // steps whose ends miss the cuts
  scene.method.table_size = 64;
  scene.method.table_size_given = true;
  scene.method.iterations = 8;
  set_clip(scene.volume, oblique_cut());
  const SceneRenderer renderer(scene);
  const Image image = renderer.render({.threads = 2});
  // float paths: a float rounding a step; double: the tables' and exp's
  // roundings. preint2-dual's table interpolates 1 - exp(-tau l) linearly
  // between its 64 chord lengths: 8.6e-5 on this view unclipped, 1.6e-4 clipped.
  const double tolerance = c.method == "preint2-dual" ? 3e-4 : c.float_math ? 2e-5 : 1e-6;
  int cut = 0, whole = 0;
  const GridVolume& grid = scene.grid();
  for (int py = 0; py < image.height(); ++py)
    for (int px = 0; px < image.width(); ++px) {
      const Ray ray = renderer.camera().ray(px, py);
      const double L = kept_length(ray, oblique_cut(), grid.box_lo(), grid.box_hi());
      double L_box = 0;
      if (const auto iv = clip_to_box(ray, grid.box_lo(), grid.box_hi())) L_box = iv->length();
      (L < L_box - 1e-9 ? cut : whole) += L_box > 0;
      const double alpha = 1 - std::exp(-kTau * L);
      const auto p = image.pixel(px, py);
      for (int ch = 0; ch < 3; ++ch)
        EXPECT_NEAR(p[ch], kColour[ch] * alpha, tolerance) << c.method << " pixel " << px << "," << py;
      EXPECT_NEAR(p[3], alpha, tolerance) << c.method << " pixel " << px << "," << py;
    }
  EXPECT_GT(cut, 60);  // the view sees the cuts
}

std::vector<ClipCase> clip_cases() {
  std::vector<ClipCase> cases;
  for (const std::string& m : grid_methods())
    for (bool f : {true, false}) cases.push_back({m, f});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Clip, ClipEveryGridMethod, ::testing::ValuesIn(clip_cases()),
                         [](const auto& info) {
                           std::string name = info.param.method + (info.param.float_math ? "_float" : "_double");
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

// The skipping of empty space leaps from the cut, not from the box: a
// field half empty gives the same bytes with and without it.
TEST(Clip, SkippingEmptySpaceChangesNoByteOfAClippedRender) {
  GridVolume grid = test::volume_from({17, 17, 17}, [](double x, double y, double z) { return x > 0.5 ? x + y + z : 0.0; },
                                      {0.0625, 0.0625, 0.0625});
  Scene scene{grid, TransferFunction({{0, 0, 0, 0, 0}, {0.6, 0, 0, 0, 0}, {0.7, 1, 0.5, 0.2, 4}, {3, 0.2, 0.5, 1, 6}}),
              view(), Lighting{}, {0, 0, 0}, MethodSpec{}};
  set_clip(scene.volume, oblique_cut());
  for (const std::string method : {"riemann", "preint1", "preint2"}) {
    scene.method.name = method;
    scene.method.step = 0.4;
    scene.method.table_size = 64;
    scene.method.table_size_given = true;
    scene.method.fast.skip_empty = true;
    const Image skipped = SceneRenderer(scene).render({.threads = 2});
    scene.method.fast.skip_empty = false;
    const Image walked = SceneRenderer(scene).render({.threads = 1});
    EXPECT_EQ(test::pixels(skipped), test::pixels(walked)) << method;
  }
}

// Issue 50's metamorphic test: a crop box equal to a sub-volume's box,
// rendered with exact, is that sub-volume rendered as its own (<= 1e-6).
TEST(Clip, CropBoxEqualsTheSubVolumeAsItsOwnFile) {
  const Vec3 spacing{0.5, 0.4, 0.3}, origin{1, -2, 0.5};
  const auto f = [](double x, double y, double z) { return 2 + std::sin(1.3 * x) * std::cos(0.9 * y) + 0.5 * std::sin(2.1 * z); };
  const GridVolume whole = test::volume_from({17, 17, 17}, f, spacing, origin);
  const std::array<int, 3> lo{3, 2, 5}, hi{12, 14, 16};  // the sub-volume's points
  const Vec3 sub_origin{origin.x + lo[0] * spacing.x, origin.y + lo[1] * spacing.y, origin.z + lo[2] * spacing.z};
  const GridVolume sub = test::volume_from({hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1}, f, spacing, sub_origin);
  std::mt19937 rng(7);
  const TransferFunction tf = test::random_tf(rng, 3.5, 2.0);
  CameraSpec camera;
  camera.eye = {12, 9, 14};
  camera.target = {5, 1.2, 3};
  camera.up = {0, 0, 1};
  camera.fov_y = 45;
  camera.width = 32;
  camera.height = 28;
  MethodSpec exact;
  exact.name = "exact";
  Scene cropped{whole, tf, camera, Lighting{}, {0, 0, 0}, exact};
  set_clip(cropped.volume, ClipRegion{{}, Box{sub.box_lo(), sub.box_hi()}});
  const Scene own{sub, tf, camera, Lighting{}, {0, 0, 0}, exact};
  const Image a = SceneRenderer(cropped).render({.threads = 2}), b = SceneRenderer(own).render({.threads = 2});
  double worst = 0, seen = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) {
    worst = std::max(worst, std::abs(double(a.data()[i]) - b.data()[i]));
    seen = std::max(seen, double(b.data()[i]));
  }
  EXPECT_LE(worst, 1e-6);
  EXPECT_GT(seen, 0.05);  // the sub-volume is seen
}

// Tetrahedral meshes: tet-raycast and exact trim each tetrahedron's chord
// at the cut (the scalars there from the tetrahedron's linear field).
TEST(Clip, MeshMethodsIntegrateToTheCut) {
  // The unit grid's points tetrahedralised: x + 2y + z on [0, 8]^3, scaled to [0, 1]^3.
  const TetMesh grid_mesh = tetrahedralize(unit_grid(), 5);
  for (const std::string method : {"tet-raycast", "exact"}) {
    Scene scene{grid_mesh, flat_tf(), view(), Lighting{}, {0, 0, 0}, MethodSpec{}};
    scene.method.name = method;
    scene.method.table_size = 64;
    scene.method.table_size_given = true;
    set_clip(scene.volume, oblique_cut());
    const SceneRenderer renderer(scene);
    const Image image = renderer.render({.threads = 2});
    const TetMesh& mesh = scene.mesh();
    for (int py = 0; py < image.height(); ++py)
      for (int px = 0; px < image.width(); ++px) {
        const double L = kept_length(renderer.camera().ray(px, py), oblique_cut(), mesh.box_lo(), mesh.box_hi());
        // tet-raycast: its (length, s_f, s_b) table interpolates 1 - exp(-tau l) linearly in l
        EXPECT_NEAR(image.pixel(px, py)[3], 1 - std::exp(-kTau * L), method == "exact" ? 1e-6 : 3e-4)
            << method << " pixel " << px << "," << py;
      }
  }
}

TEST(Clip, ProjectedTetrahedraRefuseItInOneLine) {
  Scene scene{tetrahedralize(unit_grid(), 5), flat_tf(), view(), Lighting{}, {0, 0, 0}, MethodSpec{}};
  scene.method.name = "pt";
  set_clip(scene.volume, oblique_cut());
  try {
    SceneRenderer renderer(scene);
    FAIL() << "pt rendered a clipped mesh";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot cut them at a clip plane; use exact or tet-raycast"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vri
