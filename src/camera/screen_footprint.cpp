#include "camera/screen_footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vri {

namespace {

using Point = std::array<double, 2>;

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Andrew's monotone chain: the hull of the points, without collinear ones.
std::vector<Point> convex_hull(std::vector<Point> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Point> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
  return hull;
}

constexpr double kMargin = 1;  // pixels

// The projections of the box's corners; false where one lies at or behind
// the eye's plane or projects to no finite point.
bool project_corners(const Camera& camera, const Box& box, std::vector<Point>& corners) {
  corners.clear();
  const Vec3 eye = camera.spec().eye, view = camera.spec().target - eye;
  for (int c = 0; c < 8; ++c) {
    const Vec3 corner{c & 1 ? box.hi.x : box.lo.x, c & 2 ? box.hi.y : box.lo.y, c & 4 ? box.hi.z : box.lo.z};
    const auto p = camera.project(corner);
    if (!(dot(corner - eye, view) > 0) || !p || !std::isfinite(p->first) || !std::isfinite(p->second)) return false;
    corners.push_back({p->first, p->second});
  }
  return true;
}

}  // namespace

ScreenFootprint::ScreenFootprint(const Camera& camera) : width_(camera.width()), height_(camera.height()) {}

ScreenFootprint::ScreenFootprint(const Camera& camera, const Footprint& footprint) : ScreenFootprint(camera) {
  std::vector<Point> corners;
  if (!project_corners(camera, footprint.bounds, corners)) return;  // every pixel
  hull_ = convex_hull(corners);
  all_ = false;
  if (footprint.parts.empty()) return;
  blocks_x_ = (width_ + 3) / 4;
  const int blocks_y = (height_ + 1) / 2;
  std::vector<unsigned char> blocks(std::size_t(blocks_x_) * blocks_y, 0);
  for (const Box& part : footprint.parts) {
    if (!project_corners(camera, part, corners)) return;  // every block
    double lo[2] = {corners[0][0], corners[0][1]}, hi[2] = {lo[0], lo[1]};
    for (const Point& p : corners)
      for (int a = 0; a < 2; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
    // The pixels whose centres lie within the margin of the rectangle, as blocks.
    const auto first = [](double v, int n) {
      return static_cast<int>(std::clamp(std::ceil(v - kMargin - 0.5), 0.0, double(n)));
    };
    const auto last = [](double v, int n) {
      return static_cast<int>(std::clamp(std::floor(v + kMargin - 0.5), -1.0, double(n - 1)));
    };
    const int x0 = first(lo[0], width_), x1 = last(hi[0], width_);
    const int y0 = first(lo[1], height_), y1 = last(hi[1], height_);
    if (x0 > x1 || y0 > y1) continue;
    for (int by = y0 / 2; by <= y1 / 2; ++by)
      std::fill_n(blocks.begin() + std::ptrdiff_t(by) * blocks_x_ + x0 / 4, x1 / 4 - x0 / 4 + 1, 1);
  }
  blocks_ = std::move(blocks);
}

bool ScreenFootprint::sees(int x0, int x1, int y0, int y1) const {
  if (blocks_.empty()) return true;
  for (int by = y0 / 2; by <= (y1 - 1) / 2; ++by)
    for (int bx = x0 / 4; bx <= (x1 - 1) / 4; ++bx)
      if (blocks_[std::size_t(by) * blocks_x_ + bx]) return true;
  return false;
}

ScreenFootprint::Span ScreenFootprint::rows(int y0, int y1) const {
  if (all_) return {0, width_};
  // The band of the rows' centres y + 0.5, widened by the margin, against
  // the hull: its vertices inside the band and its edges' crossings of the
  // band's two lines bound the part of the hull in the band.
  const double lo = y0 + 0.5 - kMargin, hi = y1 - 0.5 + kMargin;
  double x_min = std::numeric_limits<double>::infinity(), x_max = -x_min;
  const auto take = [&](double x) { x_min = std::min(x_min, x), x_max = std::max(x_max, x); };
  const std::size_t n = hull_.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = hull_[i];
    if (a[1] >= lo && a[1] <= hi) take(a[0]);
    if (n < 2) continue;
    const Point& b = hull_[(i + 1) % n];
    for (const double y : {lo, hi})
      if ((a[1] - y) * (b[1] - y) < 0) take(a[0] + (y - a[1]) * (b[0] - a[0]) / (b[1] - a[1]));
  }
  if (!(x_min <= x_max)) return {0, 0};
  // Pixel x's centre x + 0.5 within the margin of [x_min, x_max].
  const auto clamp = [&](double v) { return static_cast<int>(std::clamp(v, 0.0, double(width_))); };
  return {clamp(std::ceil(x_min - kMargin - 0.5)), clamp(std::floor(x_max + kMargin - 0.5) + 1)};
}

}  // namespace vri
