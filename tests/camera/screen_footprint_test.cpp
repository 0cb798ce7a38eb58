#include "camera/screen_footprint.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace vri {
namespace {

// Which pixels' rays meet the footprint (clip_to_box, as GridVolume::clip,
// on its parts or else its bounds), and which pixels ScreenFootprint keeps,
// row pair by row pair and block by block as the renderer asks.
struct Coverage {
  std::vector<char> hit, kept;
};
Coverage coverage(const Camera& camera, const Footprint& footprint) {
  const int W = camera.width(), H = camera.height();
  const ScreenFootprint seen(camera, footprint);
  const std::vector<Box> boxes = footprint.parts.empty() ? std::vector<Box>{footprint.bounds} : footprint.parts;
  Coverage c{std::vector<char>(std::size_t(W) * H), std::vector<char>(std::size_t(W) * H)};
  for (int y = 0; y < H; y += 2) {
    const int y1 = std::min(H, y + 2);
    const ScreenFootprint::Span span = seen.rows(y, y1);
    for (int py = y; py < y1; ++py)
      for (int x = 0; x < W; ++x) {
        const Ray ray = camera.ray(x, py);
        for (const Box& b : boxes) c.hit[std::size_t(py) * W + x] |= clip_to_box(ray, b.lo, b.hi).has_value();
        const int bx = x / 4 * 4;  // its block of 4 x 2 pixels, as the renderer's 16-pixel tiles make them
        c.kept[std::size_t(py) * W + x] = x >= span.x0 && x < span.x1 && seen.sees(bx, std::min(W, bx + 4), y, y1);
      }
  }
  return c;
}

// Every pixel whose ray meets the box is kept, for boxes and cameras drawn
// at random (perspective and orthographic, wide and narrow, the box
// anywhere in front of the eye and partly outside the image), and the kept
// pixels that miss lie within three pixels of one that hits (a pixel of
// margin, and the rows' pair and its margin on a slanted edge): the footprint is
// the box's silhouette, not its bounding rectangle. (A bounding rectangle
// keeps whole corners of a turned box; the test counts them.)
TEST(ScreenFootprint, KeepsEveryPixelWhoseRayMeetsTheBoxAndLittleElse) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  long long hits = 0, culled = 0;
  for (int trial = 0; trial < 60; ++trial) {
    CameraSpec spec;
    spec.width = 40 + trial % 7 * 5;
    spec.height = 30 + trial % 5 * 7;
    spec.eye = {20 * u(rng), 20 * u(rng), 20 * u(rng)};
    spec.target = {2 * u(rng), 2 * u(rng), 2 * u(rng)};
    spec.up = {u(rng), 1, u(rng)};
    spec.fov_y = 20 + 40 * (u(rng) + 1);
    if (trial % 3 == 0) spec.projection = Projection::Orthographic, spec.ortho_height = 8 + 6 * u(rng);
    const Vec3 c{3 * u(rng), 3 * u(rng), 3 * u(rng)}, half{1 + u(rng) * 0.9, 1 + u(rng) * 0.9, 1 + u(rng) * 0.9};
    const Box box{c - half, c + half};
    if (spec.projection == Projection::Perspective) {  // the eye outside the box (else every pixel is kept)
      const Vec3 e = spec.eye;
      if (e.x > box.lo.x - 0.5 && e.x < box.hi.x + 0.5 && e.y > box.lo.y - 0.5 && e.y < box.hi.y + 0.5 &&
          e.z > box.lo.z - 0.5 && e.z < box.hi.z + 0.5)
        continue;
    }
    const Camera camera(spec);
    const Coverage cov = coverage(camera, Footprint{box, {}});
    const int W = spec.width, H = spec.height;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const std::size_t i = std::size_t(y) * W + x;
        ASSERT_TRUE(!cov.hit[i] || cov.kept[i]) << "trial " << trial << " pixel " << x << " " << y;
        hits += cov.hit[i];
        culled += !cov.kept[i];
        if (!cov.kept[i] || cov.hit[i]) continue;
        bool near = false;  // a hit within three pixels
        for (int dy = -3; dy <= 3 && !near; ++dy)
          for (int dx = -3; dx <= 3 && !near; ++dx) {
            const int nx = x + dx, ny = y + dy;
            near = nx >= 0 && ny >= 0 && nx < W && ny < H && cov.hit[std::size_t(ny) * W + nx];
          }
        // At the image's edges the hull's rows reach further than the pixels that see the box.
        if (x < 3 || y < 3 || x >= W - 3 || y >= H - 3) continue;
        ASSERT_TRUE(near) << "trial " << trial << " keeps pixel " << x << " " << y << ", far from the box";
      }
  }
  EXPECT_GT(hits, 3000);  // the draws see the box
  EXPECT_GT(culled, 100000);  // and cull most of the others (the boxes are small in the image)
}

// A footprint of parts (EmptySpace::occupied_parts: runs of non-empty macro
// cells) keeps every pixel whose ray meets a part, and none of the many
// whose rays pass between two parts far apart, which its bounds keep.
TEST(ScreenFootprint, PartsLeaveOutThePixelsBetweenThem) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  long long between = 0;
  for (int trial = 0; trial < 20; ++trial) {
    CameraSpec spec;
    spec.width = 64, spec.height = 48;
    spec.eye = {30 * u(rng), 30 * u(rng), 40 + 5 * u(rng)};
    spec.target = {0, 0, 0};
    spec.fov_y = 40;
    if (trial % 2) spec.projection = Projection::Orthographic, spec.ortho_height = 16;
    const Box a{{-6, -6, -2}, {-4, -3, 1}}, b{{3.5, 4, -1}, {6, 6, 2}};
    const Footprint parts{{{-6, -6, -2}, {6, 6, 2}}, {a, b}};
    const Camera camera(spec);
    const Coverage with = coverage(camera, parts), bounds = coverage(camera, Footprint{parts.bounds, {}});
    for (std::size_t i = 0; i < with.hit.size(); ++i) {
      ASSERT_TRUE(!with.hit[i] || with.kept[i]) << "trial " << trial << " pixel " << i;
      between += bounds.kept[i] && !with.kept[i];
    }
  }
  EXPECT_GT(between, 10000);
}

// Where a corner lies at or behind the eye (the eye inside the box, or the
// box straddling the eye's plane), every pixel is kept.
TEST(ScreenFootprint, KeepsEveryPixelWhereTheBoxReachesBehindTheEye) {
  CameraSpec spec;
  spec.eye = {0, 0, 0};
  spec.target = {0, 0, -1};
  spec.width = 30;
  spec.height = 20;
  const Camera camera(spec);
  for (const Box& box : {Box{{-1, -1, -1}, {1, 1, 1}}, Box{{5, 5, -3}, {6, 6, 2}}})
    for (int y = 0; y < 20; y += 2) {
      const auto span = ScreenFootprint(camera, Footprint{box, {}}).rows(y, y + 2);
      EXPECT_EQ(span.x0, 0);
      EXPECT_EQ(span.x1, 30);
    }
  // A box behind the eye is not culled either (only kept): the rays miss it anyway.
  const auto behind = ScreenFootprint(camera, Footprint{Box{{-1, -1, 2}, {1, 1, 3}}, {}}).rows(0, 2);
  EXPECT_EQ(behind.x1 - behind.x0, 30);
}

}  // namespace
}  // namespace vri
