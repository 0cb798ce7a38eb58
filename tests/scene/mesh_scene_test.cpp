// Scenes whose volume is a tetrahedral mesh (SPEC §2, §8).
#include <gtest/gtest.h>

#include <string>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

const std::string kRest = R"("transfer_function": {"points": [[0, 1, 1, 1, 0.1], [4, 1, 0, 0, 0.5]]},
  "camera": {"eye": [30, 0, 0], "target": [0, 0, 0], "width": 8, "height": 8})";

Scene scene(const std::string& volume, const std::string& method = "exact") {
  return parse_scene("{\"volume\": " + volume + ", \"method\": {\"name\": \"" + method + "\", \"table_size\": 16, " +
                         "\"length_samples\": 4}, " + kRest + "}",
                     test::source_path("scenes"));
}

void expect_refused(auto&& f, const std::string& fragment) {
  try {
    f();
    ADD_FAILURE() << "expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(MeshScene, LoadsAMeshFileWithNamedScalars) {
  const Scene s = scene(R"({"file": "../tests/data/mesh/base64.vtu", "scalars": "height"})", "tet-raycast");
  EXPECT_EQ(s.mesh().size(), 160u);
  EXPECT_NEAR(s.mesh().max_value(), 7.1407, 1e-4);  // height = z
  EXPECT_EQ(s.method.length_samples, 4);
  EXPECT_EQ(make_integrator(s.method, s.mesh(), s.transfer_function)->name(), "tet-raycast");
  expect_refused([&] { s.grid(); }, "is a tetrahedral mesh, not a regular grid");
}

TEST(MeshScene, TetrahedralizesABuiltinGrid) {
  const Scene s = scene(R"({"builtin": "tetrahedralized", "tets_per_cell": 6,
                            "grid": {"builtin": "sphere", "dims": [5, 4, 3], "spacing": [2, 1, 1]}})");
  EXPECT_EQ(s.mesh().size(), 4u * 3 * 2 * 6);
  EXPECT_EQ(s.mesh().box_hi().x, 8);
  EXPECT_EQ(make_integrator(s.method, s.mesh(), s.transfer_function)->name(), "exact");
}

TEST(MeshScene, RefusesMismatchedMethodsAndKeys) {
  const Scene mesh = scene(R"({"file": "../data/tetra_mesh_small_ascii.vtk"})", "riemann");
  expect_refused([&] { make_integrator(mesh.method, mesh.mesh(), mesh.transfer_function); },
                 "method 'riemann' works on regular grids only");
  const Scene grid = scene(R"({"builtin": "sphere", "dims": [4, 4, 4]})", "tet-raycast");
  expect_refused([&] { make_integrator(grid.method, grid.grid(), grid.transfer_function); },
                 "method 'tet-raycast' needs a tetrahedral mesh");
  expect_refused([] { scene(R"({"file": "../data/tetra_mesh_small_ascii.vtk", "spacing": [1, 1, 1]})"); },
                 "volume.spacing: applies to grid volumes, not to meshes");
  expect_refused([] { scene(R"({"file": "../data/tetra_mesh_small_ascii.vtk", "scalars": "rho"})"); },
                 "volume: mesh '");
  expect_refused([] { scene(R"({"builtin": "tetrahedralized"})"); }, "needs a 'grid'");
  Lighting lit;
  lit.enabled = true;
  lit.mode = "interpolated";
  Scene raycast = scene(R"({"file": "../data/tetra_mesh_small_ascii.vtk"})", "tet-raycast");
  raycast.method.table_size = 16;
  // Mode interpolated is taken by tet-raycast (pt-cylindrical refuses it: test_projected).
  EXPECT_EQ(make_integrator(raycast.method, raycast.mesh(), raycast.transfer_function, lit)->name(), "tet-raycast");
  expect_refused([] { scene(R"({"builtin": "tetrahedralized", "tets_per_cell": 4, "grid": {"builtin": "sphere"}})"); },
                 "5 or 6");
}

}  // namespace
}  // namespace vri
