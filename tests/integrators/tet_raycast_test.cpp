#include "vri/integrators/tet_raycast.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_test_support.hpp"
#include "vri/camera/camera.hpp"
#include "vri/core/error.hpp"
#include "vri/integrators/mesh_exact.hpp"
#include "vri/io/vtk_legacy.hpp"
#include "tables/length_table_support.hpp"

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

TEST(TetRaycast, RefusesATableTooShortForTheMesh) {
  const TetMesh mesh = test::unit_tet();
  EXPECT_THROW(TetRaycastIntegrator(mesh, test::length_table_ptr(tf(), 8, 4, 1.0)), Error);
}

}  // namespace
}  // namespace vri
