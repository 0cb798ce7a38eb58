#include "methods/projected/projected_tetrahedra.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "mesh/mesh_test_support.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "methods/exact/mesh_exact.hpp"
#include "methods/tet_raycast/tet_raycast.hpp"
#include "io/vtk_legacy.hpp"
#include "tables/length_table_support.hpp"
#include "tables/weighted_tables.hpp"

namespace vri {
namespace {

double wave(double x, double y, double z) { return 0.5 + 0.4 * std::sin(0.9 * x + 0.5 * y) * std::cos(0.7 * z); }

const TransferFunction& tf() {
  static const TransferFunction t({{0, 0, 0, 1, 0}, {0.3, 0, 1, 0, 0.2}, {0.6, 1, 1, 0, 1.2}, {1, 1, 0, 0, 0.4}});
  return t;
}

struct Errors {
  double vs_raycast = 0, vs_exact = 0, alpha = 0;
};

// pt against tet-raycast with the same table (the same segments, so they
// agree to rounding) and against exact (the table's own error).
Errors compare(const TetMesh& mesh, const TransferFunction& t, CameraSpec cs, const Lighting& light = {}) {
  cs.width = cs.height = 40;
  const Camera cam(cs);
  auto table = test::length_table_ptr(t, 64, 16, mesh.max_edge_length());
  const Image pt = render_projected(cam, mesh, *table, {.threads = 2}, light);
  const TetRaycastIntegrator raycast(mesh, std::move(table), light);
  const MeshExactIntegrator exact(mesh, t, 1e-8, light);
  Errors e;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const Ray r = cam.ray(x, y);
      const Rgba a = raycast.integrate(r), b = exact.integrate(r);
      e.alpha += b[3];
      for (int c = 0; c < 4; ++c) {
        e.vs_raycast = std::max(e.vs_raycast, std::abs(pt.pixel(x, y)[c] - a[c]));
        e.vs_exact = std::max(e.vs_exact, std::abs(pt.pixel(x, y)[c] - b[c]));
      }
    }
  return e;
}

CameraSpec view(Vec3 eye, Vec3 target, bool ortho) {
  CameraSpec cs;
  cs.eye = eye;
  cs.target = target;
  if (ortho) {
    cs.projection = Projection::Orthographic;
    cs.ortho_height = 12;
  }
  return cs;
}

TEST(ProjectedTetrahedra, MatchesRaycastOnAConvexMesh) {
  const TetMesh mesh = tetrahedralize(test::volume_from({6, 6, 6}, wave), 5);
  for (bool ortho : {false, true}) {
    const Errors e = compare(mesh, tf(), view({13, -8, 10}, {2.5, 2.5, 2.5}, ortho));
    EXPECT_GT(e.alpha, 100);
    EXPECT_LT(e.vs_raycast, 1e-5) << "ortho " << ortho;
    EXPECT_LT(e.vs_exact, 0.02) << "ortho " << ortho;
  }
}

TEST(ProjectedTetrahedra, LitMatchesLitRaycast) {
  // The same chords lit with the same normal (`sampled`): pt agrees with
  // tet-raycast to rounding, and with lit exact to the table's and the
  // one-normal-per-chord error.
  const TetMesh mesh = tetrahedralize(test::volume_from({6, 6, 6}, wave), 5);
  const Lighting light{true, 0.3, 0.7, 0.4, 32, "sampled"};
  const Errors e = compare(mesh, tf(), view({13, -8, 10}, {2.5, 2.5, 2.5}, false), light);
  EXPECT_GT(e.alpha, 100);
  EXPECT_LT(e.vs_raycast, 1e-5);
  EXPECT_LT(e.vs_exact, 0.05);
}

// Mode interpolated (Lum, Wilson & Ma 2004): pt reads the weighted tables
// for the same chords as tet-raycast, lit with the terms at both ends, so the
// two agree to rounding; the same bytes with any thread count or tile size.
// pt-cylindrical, and pt without weighted tables, refuse the mode.
TEST(ProjectedTetrahedra, InterpolatedLightingMatchesRaycast) {
  const TetMesh mesh = tetrahedralize(test::volume_from({6, 6, 6}, wave), 5);
  const Lighting light{true, 0.3, 0.7, 0.4, 32, "interpolated"};
  CameraSpec cs = view({13, -8, 10}, {2.5, 2.5, 2.5}, false);
  cs.width = cs.height = 32;
  const Camera cam(cs);
  const DiscreteTf d(tf(), 64);
  auto weighted = std::make_unique<WeightedLengthTables>(build_weighted_length_tables(d, 16, mesh.max_edge_length()));
  auto table = test::length_table_ptr(tf(), 64, 16, mesh.max_edge_length());
  const Image pt = render_projected(cam, mesh, *table, {.threads = 1}, light, weighted.get());
  for (RenderOptions opt : {RenderOptions{2, 16}, RenderOptions{3, 5}}) {
    const Image other = render_projected(cam, mesh, *table, opt, light, weighted.get());
    ASSERT_EQ(0, std::memcmp(pt.data().data(), other.data().data(), pt.data().size() * sizeof(float)));
  }
  EXPECT_THROW(render_projected(cam, mesh, *table, {}, light), Error);
  // pt-cylindrical reads the weighted tables resampled on its planes: close to
  // pt (as unlit, CylindricalPlanesApproachPt); without them it refuses the mode.
  const CylindricalTable cylinder(*table, 64, 64);
  EXPECT_THROW(render_projected(cam, mesh, cylinder, {}, light), Error);
  const WeightedCylindricalTables wc{CylindricalTable(weighted->front, 64, 64),
                                     CylindricalTable(weighted->back, 64, 64)};
  const Image cyl = render_projected(cam, mesh, cylinder, {.threads = 1}, light, &wc);
  const Image cyl2 = render_projected(cam, mesh, cylinder, {.threads = 2, .tile_size = 7}, light, &wc);
  ASSERT_EQ(0, std::memcmp(cyl.data().data(), cyl2.data().data(), cyl.data().size() * sizeof(float)));
  const Image sampled = render_projected(cam, mesh, *table, {}, {true, 0.3, 0.7, 0.4, 32, "sampled"});
  const TetRaycastIntegrator raycast(mesh, std::move(table), light, std::move(weighted));
  double vs_raycast = 0, vs_sampled = 0, vs_cylinder = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const Rgba a = raycast.integrate(cam.ray(x, y));
      for (int c = 0; c < 4; ++c) {
        vs_raycast = std::max(vs_raycast, std::abs(pt.pixel(x, y)[c] - a[c]));
        vs_sampled = std::max(vs_sampled, double(std::abs(pt.pixel(x, y)[c] - sampled.pixel(x, y)[c])));
        vs_cylinder = std::max(vs_cylinder, double(std::abs(pt.pixel(x, y)[c] - cyl.pixel(x, y)[c])));
      }
    }
  EXPECT_LT(vs_raycast, 1e-5);
  EXPECT_GT(vs_sampled, 1e-3);  // the mode changes the image
  EXPECT_LT(vs_cylinder, 0.01);  // measured 3.7e-3; the mode itself changes pixels by 8.4e-2
}

TEST(ProjectedTetrahedra, MatchesRaycastOnANonConvexMesh) {
  // A tunnel, a notch and a detached block: several layers per pixel, with gaps.
  const TetMesh mesh = test::carved_mesh(7, wave, [](double x, double y, double z) {
    return !(x > 2 && x < 4 && y > 2 && y < 4) && !(z > 4 && y < 2) && !(x > 4 && x < 5);
  }, 6);
  for (bool ortho : {false, true}) {
    const Errors e = compare(mesh, tf(), view({-9, 14, 12}, {3, 3, 3}, ortho));
    EXPECT_GT(e.alpha, 100);
    EXPECT_LT(e.vs_raycast, 1e-5) << "ortho " << ortho;
    EXPECT_LT(e.vs_exact, 0.02) << "ortho " << ortho;
  }
}

TEST(ProjectedTetrahedra, MatchesRaycastOnTheBundledMesh) {
  const TetMesh mesh = read_vtk_legacy(test::source_path("data/tetra_mesh_small_ascii.vtk"));
  const TransferFunction t({{0, 0, 0, 1, 0.02}, {2, 0, 1, 0, 0.1}, {4, 1, 0, 0, 0.3}});
  const Errors e = compare(mesh, t, view({30, 20, 25}, {0, 0, 0}, false));
  EXPECT_LT(e.vs_raycast, 1e-5);
}

// The papers' reconstruction (PtReconstruction::PerVertex): under an
// orthographic camera the interpolation is linear either way and a single
// tetrahedron has nothing to sort, so it is vri's pt to the byte; under a
// perspective camera its screen-linear (l, s_f, s_b) departs from each
// pixel's ray, less as the eye moves away (the perspective flattens).
TEST(ProjectedTetrahedra, PerVertexReconstructionIsThePapers) {
  const TetMesh one({{0, 0, 0}, {4, 0, 0}, {0, 4, 0}, {0, 0, 4}}, {{0, 1, 2, 3}}, {0.1, 0.9, 0.5, 0.7});
  const LengthTable table = test::length_table(tf(), 64, 16, one.max_edge_length());
  const auto difference = [&](const CameraSpec& spec) {
    CameraSpec cs = spec;
    cs.width = cs.height = 48;
    const Camera cam(cs);
    const Image a = render_projected(cam, one, table), b = render_projected(cam, one, table, {}, {}, nullptr,
                                                                           PtReconstruction::PerVertex);
    double worst = 0;
    for (std::size_t i = 0; i < a.data().size(); ++i) worst = std::max(worst, double(std::abs(a.data()[i] - b.data()[i])));
    return worst;
  };
  CameraSpec ortho = view({9, 7, 8}, {1, 1, 1}, true);
  ortho.ortho_height = 7;
  EXPECT_EQ(difference(ortho), 0.0);
  CameraSpec near = view({5, 4, 4.5}, {1, 1, 1}, false), far = view({21, 17, 19}, {1, 1, 1}, false);
  near.fov_y = 70, far.fov_y = 17;  // about the same image of the tetrahedron
  const double d_near = difference(near), d_far = difference(far);
  EXPECT_GT(d_near, 1e-3);
  EXPECT_LT(d_far, 0.5 * d_near);
}

// Visibility order: two slabs, red in front of blue seen from one side and
// blue in front of red from the other; nearly opaque, so the order decides.
TEST(ProjectedTetrahedra, NearerSlabCoversTheFartherOne) {
  const TetMesh mesh = test::carved_mesh(5, [](double x, double, double) { return x < 2 ? 0.0 : 1.0; },
                                         [](double x, double, double) { return x < 1 || x > 3; });
  const TransferFunction t({{0, 1, 0, 0, 8}, {0.01, 0, 0, 0, 0}, {0.99, 0, 0, 0, 0}, {1, 0, 0, 1, 8}});
  const LengthTable table = test::length_table(t, 32, 8, mesh.max_edge_length());
  for (double side : {-1.0, 1.0}) {
    CameraSpec cs = view({2 + 10 * side, 2.1, 2.2}, {2, 2.1, 2.2}, true);
    cs.ortho_height = 2;
    cs.width = cs.height = 8;
    const Image img = render_projected(Camera(cs), mesh, table, {.threads = 2});
    const float* p = img.pixel(4, 4);
    EXPECT_GT(p[3], 0.99);
    // From x < 0 the red slab (s = 0, x in [0, 1]) is in front, from x > 4 the blue one.
    EXPECT_GT(side < 0 ? p[0] : p[2], 0.99) << side;
    EXPECT_LT(side < 0 ? p[2] : p[0], 0.01) << side;
  }
}

TEST(ProjectedTetrahedra, SameBytesWithAnyThreadCountAndTileSize) {
  const TetMesh mesh = test::carved_mesh(6, wave, [](double x, double y, double) { return x < 2 || y > 3; });
  const LengthTable table = test::length_table(tf(), 32, 8, mesh.max_edge_length());
  CameraSpec cs = view({-6, -5, 9}, {2.5, 2.5, 2.5}, false);
  cs.width = 37;
  cs.height = 29;
  const Camera cam(cs);
  const Image one = render_projected(cam, mesh, table, {.threads = 1});
  for (RenderOptions opt : {RenderOptions{2, 16}, RenderOptions{3, 5}, RenderOptions{2, 64}}) {
    const Image other = render_projected(cam, mesh, table, opt);
    ASSERT_EQ(0, std::memcmp(one.data().data(), other.data().data(), one.data().size() * sizeof(float)));
  }
}

// pt-cylindrical reads the same table through cylinder planes: close to pt,
// and closer with finer planes.
TEST(ProjectedTetrahedra, CylindricalPlanesApproachPt) {
  const TetMesh mesh = test::carved_mesh(6, wave, [](double x, double, double z) { return !(x > 2 && x < 3 && z > 1); });
  const LengthTable table = test::length_table(tf(), 32, 16, mesh.max_edge_length());
  CameraSpec cs = view({13, -8, 10}, {2.5, 2.5, 2.5}, true);
  cs.width = cs.height = 32;
  const Camera cam(cs);
  const Image pt = render_projected(cam, mesh, table);
  auto error = [&](int size, int planes) {
    const Image cyl = render_projected(cam, mesh, CylindricalTable(table, size, planes));
    double e = 0;
    for (std::size_t i = 0; i < pt.data().size(); ++i) e = std::max(e, double(std::abs(pt.data()[i] - cyl.data()[i])));
    return e;
  };
  const double coarse = error(32, 16), fine = error(128, 128);
  EXPECT_LT(coarse, 0.05);
  EXPECT_LT(fine, 0.5 * coarse);
}

// The projected points, the tile lists and each tile's fragments grow with
// the mesh, the image and the depth complexity: they are charged to
// --max-memory as they are allocated (issue 47), so a render over the budget
// is refused with the flag named, and one within it gives the same bytes.
TEST(ProjectedTetrahedra, WorkingArraysAreChargedToTheMemoryBudget) {
  const TetMesh mesh = test::carved_mesh(6, wave, [](double x, double y, double) { return x < 2 || y > 3; });
  const LengthTable table = test::length_table(tf(), 32, 8, mesh.max_edge_length());
  CameraSpec cs = view({-6, -5, 9}, {2.5, 2.5, 2.5}, false);
  cs.width = cs.height = 24;
  const Camera cam(cs);
  const Image free = render_projected(cam, mesh, table, {.threads = 1});
  struct Restore {
    ~Restore() { set_memory_limit(0); }
  } restore;
  const std::uint64_t image = free.data().size() * sizeof(float);  // charged as any image
  set_memory_limit(memory_in_use() + image + 2048);  // the 216 projected points alone take 6.75 KiB
  try {
    render_projected(cam, mesh, table, {.threads = 1});
    FAIL() << "the working arrays were not charged";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("a working array of 216 values"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--max-memory"), std::string::npos) << e.what();
  }
  const std::uint64_t before = memory_in_use();
  set_memory_limit(before + (16 << 20));
  const Image within = render_projected(cam, mesh, table, {.threads = 1, .tile_size = 4});
  EXPECT_EQ(memory_in_use(), before + image);  // all given back but the image
  ASSERT_EQ(0, std::memcmp(free.data().data(), within.data().data(), free.data().size() * sizeof(float)));
}

TEST(ProjectedTetrahedra, RefusesATableTooShortForTheMesh) {
  const TetMesh mesh = test::unit_tet();
  const LengthTable table = test::length_table(tf(), 8, 4, 1.0);
  CameraSpec cs = view({3, 3, 3}, {0, 0, 0}, false);
  EXPECT_THROW(render_projected(Camera(cs), mesh, table), Error);
}

}  // namespace
}  // namespace vri
