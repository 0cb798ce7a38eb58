#include "methods/tet_raycast/tet_raycast.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "mesh/mesh_test_support.hpp"
#include "vri/camera.hpp"
#include "vri/error.hpp"
#include "methods/exact/mesh_exact.hpp"
#include "io/vtk_legacy.hpp"
#include "tables/length_table_support.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "test_support.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/weighted_tables.hpp"

namespace vri {
namespace {

double wave(double x, double y, double z) { return 0.5 + 0.4 * std::sin(0.9 * x + 0.5 * y) * std::cos(0.7 * z); }

// Max over channels and pixels of |tet-raycast - exact| on a small view.
double max_error(const TetMesh& mesh, const TransferFunction& tf, int size, int lengths, CameraSpec cs,
                 const Lighting& light = {}) {
  const MeshExactIntegrator exact(mesh, tf, 1e-8, light);
  const TetRaycastIntegrator raycast(
      mesh, test::length_table_ptr(tf, size, lengths, mesh.max_edge_length()), light);
  cs.width = cs.height = 32;
  const Camera cam(cs);
  double err = 0, alpha = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const Ray r = cam.ray(x, y);
      const Rgba a = exact.integrate(r), b = raycast.integrate(r);
      alpha += a[3];
      for (int c = 0; c < 4; ++c) err = std::max(err, std::abs(a[c] - b[c]));
    }
  EXPECT_GT(alpha, 50) << "the view must hit the mesh";
  return err;
}

const TransferFunction& tf() {
  static const TransferFunction t({{0, 0, 0, 1, 0}, {0.3, 0, 1, 0, 0.2}, {0.6, 1, 1, 0, 1.2}, {1, 1, 0, 0, 0.4}});
  return t;
}

TEST(TetRaycast, ConvergesToExactOnANonConvexMesh) {
  // A block with a tunnel and a notch: rays leave and re-enter.
  const TetMesh mesh = test::carved_mesh(7, wave, [](double x, double y, double z) {
    return !(x > 2 && x < 4 && y > 2 && y < 4) && !(z > 4 && y < 2);
  });
  CameraSpec cs;
  cs.eye = {14, -9, 11};
  cs.target = {3, 3, 3};
  const double coarse = max_error(mesh, tf(), 32, 8, cs);
  const double fine = max_error(mesh, tf(), 128, 32, cs);
  EXPECT_LT(fine, 0.01);
  EXPECT_LT(fine, 0.5 * coarse);  // the table's resolution is what limits it
}

double linear(double x, double y, double z) { return 0.1 * x + 0.08 * y - 0.05 * z + 0.4; }

TEST(TetRaycast, LitConvergesToLitExact) {
  // On a linear field the normal is constant, so one normal per chord
  // (`sampled`) is exact and only the table limits the error (a curved
  // field: ProjectedTetrahedra.LitMatchesLitRaycast).
  const auto keep = [](double x, double y, double z) { return !(x > 2 && x < 4 && y > 2 && y < 4) && !(z > 4 && y < 2); };
  const Lighting light{true, 0.3, 0.7, 0.4, 32, "sampled"};
  CameraSpec cs;
  cs.eye = {14, -9, 11};
  cs.target = {3, 3, 3};
  const TetMesh flat = test::carved_mesh(7, linear, keep);
  const double coarse = max_error(flat, tf(), 16, 4, cs, light);
  const double fine = max_error(flat, tf(), 64, 16, cs, light);
  EXPECT_LT(fine, 0.01);
  EXPECT_LT(fine, 0.5 * coarse);
}

TEST(TetRaycast, MatchesExactOnTheBundledMesh) {
  const TetMesh mesh = read_vtk_legacy(test::source_path("data/tetra_mesh_small_ascii.vtk"));
  const TransferFunction t({{0, 0, 0, 1, 0.02}, {2, 0, 1, 0, 0.1}, {4, 1, 0, 0, 0.3}});
  CameraSpec cs;
  cs.eye = {30, 20, 25};
  cs.target = {0, 0, 0};
  EXPECT_LT(max_error(mesh, t, 64, 32, cs), 0.01);
}

// Interpolated lighting (Lum, Wilson & Ma 2004) on meshes: tet-raycast with
// the plain and the weighted tables of one (l, s_f, s_b) grid, built by the
// same O(N^2) machinery (incremental) so that they differ only by rounding.
std::unique_ptr<TetRaycastIntegrator> lit_raycast(const TetMesh& mesh, const TransferFunction& t, int size,
                                                  int lengths, const Lighting& light) {
  const DiscreteTf d(t, size);
  auto plain = std::make_unique<LengthTable>(build_length_table(IncrementalBuilder(), d, lengths, mesh.max_edge_length()));
  auto weighted = light.mode == "interpolated"
                      ? std::make_unique<WeightedLengthTables>(build_weighted_length_tables(d, lengths, mesh.max_edge_length()))
                      : nullptr;
  return std::make_unique<TetRaycastIntegrator>(mesh, std::move(plain), light, std::move(weighted));
}

Lighting interpolated(double ka, double kd, double ks, double p) { return {true, ka, kd, ks, p, "interpolated"}; }

CameraSpec small_view(Vec3 eye, Vec3 target, int n) {
  CameraSpec cs;
  cs.eye = eye;
  cs.target = target;
  cs.width = cs.height = n;
  return cs;
}

// Constant shading terms: a alone scales the unlit colour (the diffuse tables
// sum to C), b alone gives the opacity in r, g, b (the specular ones to alpha).
TEST(TetRaycastLighting, ConstantTermsGiveTheUnlitImage) {
  const TetMesh mesh = tetrahedralize(test::volume_from({6, 6, 6}, wave), 5);
  const Camera cam(small_view({13, -8, 10}, {2.5, 2.5, 2.5}, 24));
  const auto unlit = lit_raycast(mesh, tf(), 64, 16, {});
  const auto ambient = lit_raycast(mesh, tf(), 64, 16, interpolated(0.6, 0, 0, 32));
  const auto specular = lit_raycast(mesh, tf(), 64, 16, interpolated(0, 0, 1, 0));  // b = |N.d|^0 = 1
  double worst_a = 0, worst_b = 0, alpha = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      const Ray r = cam.ray(x, y);
      const Rgba u = unlit->integrate(r), a = ambient->integrate(r), b = specular->integrate(r);
      alpha += u[3];
      for (int c = 0; c < 3; ++c) {
        worst_a = std::max(worst_a, std::abs(a[c] - 0.6 * u[c]));
        worst_b = std::max(worst_b, std::abs(b[c] - u[3]));
      }
      worst_a = std::max(worst_a, std::abs(a[3] - u[3]));
      worst_b = std::max(worst_b, std::abs(b[3] - u[3]));
    }
  EXPECT_GT(alpha, 50);
  EXPECT_LT(worst_a, 1e-5);
  EXPECT_LT(worst_b, 1e-5);
}

// The shading error of lit tet-raycast: RMS over r, g, b and the view of
// (lit - unlit) - (lit exact - unlit exact), which removes the table's own
// (unlit) error that both lighting modes share.
double shading_error(const TetMesh& mesh, const TransferFunction& t, const Lighting& light, const Camera& cam) {
  const MeshExactIntegrator exact(mesh, t, 1e-7, light), exact_unlit(mesh, t, 1e-7);
  const auto lit = lit_raycast(mesh, t, 128, 32, light), unlit = lit_raycast(mesh, t, 128, 32, {});
  double sum = 0;
  for (int y = 0; y < cam.height(); ++y)
    for (int x = 0; x < cam.width(); ++x) {
      const Ray r = cam.ray(x, y);
      const Rgba a = lit->integrate(r), b = unlit->integrate(r), e = exact.integrate(r), f = exact_unlit.integrate(r);
      for (int c = 0; c < 3; ++c) sum += std::pow((a[c] - b[c]) - (e[c] - f[c]), 2);
    }
  return std::sqrt(sum / (3.0 * cam.width() * cam.height()));
}

// The wave on [0, 5]^3 tetrahedralised with n points a side: refining the
// mesh shortens the chords, across which the normal turns.
TetMesh wave_mesh(int n) {
  const double h = 5.0 / (n - 1);
  return tetrahedralize(test::volume_from({n, n, n}, wave, {h, h, h}), 5);
}

// Both modes converge to lit exact as the mesh is refined (the normal turns
// less across a chord). Measured (16 x 16 view, n = 6, 11, 21 points a side):
// sampled 1.44e-3, 3.31e-4, 9.5e-5; interpolated 1.74e-3, 5.12e-4, 1.62e-4.
// Interpolated is the farther one, by 1.2-1.7x, and converges no faster
// (24 x 24: 0.136 against sampled's 0.145 from n = 6 to 21; here 0.093
// against 0.066): with the opacity spread along the chord, the one normal of
// `sampled` (the mean of the end gradients is the gradient at the chord's
// midpoint, the gradient being linear) is the midpoint rule for the shading
// terms, the linear terms of `interpolated` the trapezoid rule, whose error
// is about twice as large (as on grids, docs/LIGHTING.md §4).
TEST(TetRaycastLighting, BothModesConvergeToLitExact) {
  const Camera cam(small_view({13, -8, 10}, {2.5, 2.5, 2.5}, 16));
  Lighting sampled{true, 0.3, 0.7, 0.4, 32, "sampled"}, interp = sampled;
  interp.mode = "interpolated";
  double s[3], i[3];
  for (int k = 0; k < 3; ++k) {
    const TetMesh mesh = wave_mesh(k == 0 ? 6 : k == 1 ? 11 : 21);
    s[k] = shading_error(mesh, tf(), sampled, cam);
    i[k] = shading_error(mesh, tf(), interp, cam);
  }
  EXPECT_LT(s[2], 0.1 * s[0]);
  EXPECT_LT(i[2], 0.12 * i[0]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(i[k], s[k]) << k;  // trapezoid against midpoint
    EXPECT_LT(i[k], 2 * s[k]) << k;
  }
}

TEST(TetRaycastLighting, InterpolatedSameBytesWithAnyThreadCount) {
  const TetMesh mesh = wave_mesh(6);
  const auto raycast = lit_raycast(mesh, tf(), 32, 8, interpolated(0.3, 0.7, 0.4, 32));
  const Camera cam(small_view({13, -8, 10}, {2.5, 2.5, 2.5}, 21));
  const Image one = render(cam, *raycast, {.threads = 1}), two = render(cam, *raycast, {.threads = 2, .tile_size = 5});
  ASSERT_EQ(0, std::memcmp(one.data().data(), two.data().data(), one.data().size() * sizeof(float)));
  // Without the weighted tables the mode is refused.
  EXPECT_THROW(TetRaycastIntegrator(mesh, test::length_table_ptr(tf(), 8, 4, mesh.max_edge_length()),
                                    interpolated(0.3, 0.7, 0.4, 32)),
               Error);
}

TEST(TetRaycast, RefusesATableTooShortForTheMesh) {
  const TetMesh mesh = test::unit_tet();
  EXPECT_THROW(TetRaycastIntegrator(mesh, test::length_table_ptr(tf(), 8, 4, 1.0)), Error);
}

// The (l, s_f, s_b) table is one build per length: a builder of O(n^3) work
// at a size that fits in memory ran for minutes (issue 47). Its work is
// checked against --max-work before anything is built, for every mesh
// method that looks the table up; under the cap it renders.
TEST(TetRaycast, TableWorkOverTheCapIsRefusedBeforeBuilding) {
  for (const char* method : {"tet-raycast", "pt", "pt-cylindrical"}) {
    SCOPED_TRACE(method);
    Scene scene = load_scene(test::source_path("scenes/blunt_fin.json"));
    scene.camera.width = scene.camera.height = 8;
    scene.method.name = method;
    scene.method.builder = "brute";
    scene.method.table_size = 256;
    scene.method.length_samples = 64;
    scene.method.max_work = 1e9;  // brute: 63 x 8 x 256^2 x 86 = 2.8e9, and the deeper slabs' panels
    try {
      const SceneRenderer renderer(scene);
      FAIL() << "built a table of about 3.2e9 evaluations under a cap of 1e9";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("builder 'brute' takes about 3.19381e+09 evaluations (63 lengths of 256^2 entries)"), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("--max-work"), std::string::npos) << e.what();
    }
    scene.method.table_size = 16;  // 63 x 8 x 16^2 x 6 = 7.7e5: builds
    scene.method.length_samples = 8;
    EXPECT_NO_THROW(SceneRenderer(scene, Backend::Cpu, 1).render(RenderOptions{.threads = 1}));
  }
}

}  // namespace
}  // namespace vri
