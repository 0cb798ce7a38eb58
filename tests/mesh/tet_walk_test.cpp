#include "mesh/tet_walk.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mesh/mesh_test_support.hpp"

namespace vri {
namespace {

double field(double x, double y, double z) { return 0.5 + 0.1 * x - 0.2 * y + 0.05 * z; }

// Whole cells of a 5^3-point grid (4^3 cells) removed by `hole(i, j, k)`:
// the rest is a non-convex medium with tunnels, whose length along a ray is
// the sum over kept cells of the ray's length inside each.
struct Carved {
  std::function<bool(int, int, int)> hole;
  TetMesh mesh;
  explicit Carved(std::function<bool(int, int, int)> h, int per_cell = 5)
      : hole(std::move(h)),
        mesh(test::carved_mesh(5, field, [this](double x, double y, double z) {
          return !hole(int(std::floor(x)), int(std::floor(y)), int(std::floor(z)));
        }, per_cell)) {}
  double length_inside(const Ray& ray) const {
    double sum = 0;
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
          if (!hole(i, j, k))
            if (auto iv = clip_to_box(ray, {double(i), double(j), double(k)}, {i + 1.0, j + 1.0, k + 1.0}))
              sum += iv->length();
    return sum;
  }
};

struct Walked {
  double length = 0;
  int pieces = 0, runs = 0;
  bool ordered = true, scalars_ok = true;
};

Walked walk(const TetWalk& w, const Ray& ray) {
  Walked out;
  double last = -1;
  w.for_each_segment(ray, [&](const TetSegment& s) {
    if (s.ta < last - 1e-12 || !(s.tb > s.ta)) out.ordered = false;
    if (s.ta > last + 1e-9) ++out.runs;  // a gap: the ray re-entered the medium
    last = s.tb;
    out.length += s.tb - s.ta;
    ++out.pieces;
    const Vec3 a = ray.at(s.ta), b = ray.at(s.tb);
    if (std::abs(s.s_front - field(a.x, a.y, a.z)) > 1e-6 || std::abs(s.s_back - field(b.x, b.y, b.z)) > 1e-6)
      out.scalars_ok = false;
    return true;
  });
  return out;
}

TEST(TetWalk, CrossesTwoSeparateBlocks) {
  const Carved c([](int i, int, int) { return i == 1 || i == 2; });  // slabs x in [0,1] and [3,4]
  const TetWalk w(c.mesh);
  const Ray ray{{-1, 1.3, 2.7}, {1, 0, 0}};
  const Walked r = walk(w, ray);
  EXPECT_NEAR(r.length, 2.0, 1e-12);
  EXPECT_EQ(r.runs, 2);
  EXPECT_TRUE(r.ordered);
  EXPECT_TRUE(r.scalars_ok);
}

TEST(TetWalk, RandomRaysThroughATunnelledMeshSeeEveryPiece) {
  for (int per_cell : {5, 6}) {
    // A non-convex medium: two crossing tunnels and a notch on one side.
    const Carved c([](int i, int j, int k) { return (i == 1 && j == 2) || (j == 1 && k == 2) || (i == 3 && k == 0); },
                   per_cell);
    const TetWalk w(c.mesh);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 5);
    int multi = 0;
    for (int n = 0; n < 300; ++n) {
      const Vec3 o{u(rng) - 6, u(rng), u(rng)};
      const Vec3 target{u(rng), u(rng), u(rng)};
      const Ray ray{o, normalize(target - o)};
      const Walked r = walk(w, ray);
      ASSERT_NEAR(r.length, c.length_inside(ray), 1e-9) << n;
      EXPECT_TRUE(r.ordered) << n;
      EXPECT_TRUE(r.scalars_ok) << n;
      multi += r.runs > 1;
    }
    EXPECT_GT(multi, 20);  // many rays left and re-entered the medium
  }
}

TEST(TetWalk, RaysAlongEdgesAndFacesOfTheGrid) {
  const Carved c([](int, int, int) { return false; });
  const TetWalk w(c.mesh);
  // Along grid lines (edges shared by several tetrahedra) and in grid planes.
  for (const Ray& ray : {Ray{{-2, 1, 1}, {1, 0, 0}}, Ray{{-2, 2, 0.5}, {1, 0, 0}}, Ray{{1, -3, 3}, {0, 1, 0}},
                         Ray{{-1, -1, 2}, normalize(Vec3{1, 1, 0})}, Ray{{-1, -1, -1}, normalize(Vec3{1, 1, 1})}}) {
    const Walked r = walk(w, ray);
    EXPECT_NEAR(r.length, clip_to_box(ray, {0, 0, 0}, {4, 4, 4})->length(), 1e-9);  // counted once
    EXPECT_TRUE(r.ordered);
    EXPECT_TRUE(r.scalars_ok);
  }
}

// Two blocks meeting on the plane x = 3 with points of their own: the faces
// there are coincident boundary faces (a non-conforming seam, like the
// oxygen post's), and the walk must leave and re-enter without a gap.
TEST(TetWalk, CrossesANonConformingSeam) {
  const GridVolume a = test::volume_from({4, 4, 4}, field), b = test::volume_from({4, 4, 4}, field, {1, 1, 1}, {3, 0, 0});
  const TetMesh ma = tetrahedralize(a, 6), mb = tetrahedralize(b, 5);
  std::vector<Vec3> points = ma.points();
  points.insert(points.end(), mb.points().begin(), mb.points().end());
  std::vector<float> scalars = ma.scalars();
  scalars.insert(scalars.end(), mb.scalars().begin(), mb.scalars().end());
  std::vector<TetMesh::Tet> tets = ma.tets();
  const auto offset = static_cast<std::int32_t>(ma.points().size());
  for (auto t : mb.tets()) tets.push_back({t[0] + offset, t[1] + offset, t[2] + offset, t[3] + offset});
  const TetMesh mesh(points, tets, scalars);
  const TetWalk w(mesh);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.1, 2.9);
  for (int n = 0; n < 400; ++n) {
    const Vec3 o{-4, u(rng), u(rng)}, target{6, u(rng), u(rng)};
    const Ray ray{o, normalize(target - o)};
    const Walked r = walk(w, ray);
    ASSERT_NEAR(r.length, clip_to_box(ray, {0, 0, 0}, {6, 3, 3})->length(), 1e-9) << n;
    EXPECT_TRUE(r.scalars_ok);
  }
}

TEST(TetWalk, MissesAndStartsOnlyAtTZero) {
  const TetMesh m = test::unit_tet();
  const TetWalk w(m);
  EXPECT_EQ(walk(w, Ray{{2, 2, 2}, {1, 0, 0}}).pieces, 0);
  EXPECT_EQ(walk(w, Ray{{2, 0.1, 0.1}, {1, 0, 0}}).pieces, 0);  // the tetrahedron is behind the eye
  const Walked r = walk(w, Ray{{-1, 0.1, 0.1}, {1, 0, 0}});
  EXPECT_EQ(r.pieces, 1);
  EXPECT_NEAR(r.length, 0.8, 1e-12);
}

}  // namespace
}  // namespace vri
