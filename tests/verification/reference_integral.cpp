#include "verification/reference_integral.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "vri/camera.hpp"

namespace vri::verify {

namespace {

struct Values {
  double r, g, b, tau;
};

Values lerp(const ControlPoint& a, const ControlPoint& b, double w) {
  return {a.r + w * (b.r - a.r), a.g + w * (b.g - a.g), a.b + w * (b.b - a.b), a.tau + w * (b.tau - a.tau)};
}

// SPEC §3 from the points alone: linear between points, the end values held
// outside; where points share s, the first holds from below and the last from above.
class Tf {
 public:
  explicit Tf(const std::vector<ControlPoint>& p) : p_(p) {}
  // The values just above s (from the right), and just below it (from the left).
  Values above(double s) const {
    if (s < p_.front().s) return at_point(0);
    // The last point at or below s.
    const std::size_t i = std::size_t(std::upper_bound(p_.begin(), p_.end(), s, by_s) - p_.begin()) - 1;
    if (i + 1 >= p_.size()) return at_point(i);
    const double w = (s - p_[i].s) / (p_[i + 1].s - p_[i].s);
    return lerp(p_[i], p_[i + 1], w);
  }
  Values below(double s) const {
    if (s > p_.back().s) return at_point(p_.size() - 1);
    // The first point at or above s.
    const std::size_t i = std::size_t(std::lower_bound(p_.begin(), p_.end(), s, [](const ControlPoint& q, double v) {
                                        return q.s < v;
                                      }) - p_.begin());
    if (i == 0) return at_point(0);
    const double w = (s - p_[i - 1].s) / (p_[i].s - p_[i - 1].s);
    return lerp(p_[i - 1], p_[i], w);
  }
  // The distinct point scalars strictly between a and b (a < b), ascending.
  void between(double a, double b, std::vector<double>& out) const {
    out.clear();
    auto it = std::upper_bound(p_.begin(), p_.end(), a, by_s);
    for (; it != p_.end() && it->s < b; ++it)
      if (out.empty() || out.back() != it->s) out.push_back(it->s);
  }

 private:
  static bool by_s(double v, const ControlPoint& q) { return v < q.s; }
  Values at_point(std::size_t i) const { return {p_[i].r, p_[i].g, p_[i].b, p_[i].tau}; }
  const std::vector<ControlPoint>& p_;
};

// Trilinear at a world point of the box, clamped to the grid (SPEC §1).
double trilinear(const GridVolume& v, Vec3 p) {
  const auto& d = v.dims();
  double u[3];
  int i[3];
  for (int a = 0; a < 3; ++a) {
    const double x = std::clamp((p[a] - v.origin()[a]) / v.spacing()[a], 0.0, double(d[a] - 1));
    i[a] = std::min(int(std::floor(x)), d[a] - 2);
    u[a] = x - i[a];
  }
  double s = 0;
  for (int k = 0; k < 8; ++k) {
    const int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
    const double w = (dx ? u[0] : 1 - u[0]) * (dy ? u[1] : 1 - u[1]) * (dz ? u[2] : 1 - u[2]);
    if (w != 0) s += w * v.at(i[0] + dx, i[1] + dy, i[2] + dz);
  }
  return s;
}

// Front-to-back state.
struct State {
  double T = 1, C[3] = {0, 0, 0};
};

// A piece of length len on which r, g, b, tau go linearly from a to b.
void add_linear_piece(const Values& a, const Values& b, double len, State& st) {
  if (!(len > 0) || st.T == 0) return;
  const double k = (b.tau - a.tau) / len;  // d tau / d u
  auto depth = [&](double u) { return (a.tau + 0.5 * k * u) * u; };
  // Where the depth from the piece's start reaches D (tau >= 0: D grows).
  auto reach = [&](double D) {
    const double disc = a.tau * a.tau + 2 * k * D;
    return 2 * D / (a.tau + std::sqrt(std::max(disc, 0.0)));
  };
  const double total = depth(len);
  const double end = total > 40 ? std::min(len, reach(40)) : len;
  const double shown = total > 40 ? 40 : total;
  const int panels = std::max(1, int(std::ceil(shown / 0.5)));
  static constexpr double x[4] = {-0.861136311594052575, -0.339981043584856265, 0.339981043584856265,
                                  0.861136311594052575};
  static constexpr double w[4] = {0.347854845137453857, 0.652145154862546143, 0.652145154862546143,
                                  0.347854845137453857};
  double u0 = 0;
  for (int p = 1; p <= panels; ++p) {
    const double u1 = p == panels ? end : std::min(end, reach(shown * p / panels));
    const double half = 0.5 * (u1 - u0), mid = 0.5 * (u0 + u1);
    for (int q = 0; q < 4; ++q) {
      const double u = mid + half * x[q], f = u / len;
      const double weight = half * w[q] * std::max(a.tau + k * u, 0.0) * std::exp(-depth(u));
      st.C[0] += st.T * weight * (a.r + f * (b.r - a.r));
      st.C[1] += st.T * weight * (a.g + f * (b.g - a.g));
      st.C[2] += st.T * weight * (a.b + f * (b.b - a.b));
    }
    u0 = u1;
  }
  st.T *= std::exp(-total);
}

Rgba integrate(const GridVolume& v, const Tf& tf, Ray ray) {
  ray.dir = (1 / length(ray.dir)) * ray.dir;
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();  // SPEC §4: t >= 0
  const Vec3 lo = v.box_lo(), hi = v.box_hi();
  for (int a = 0; a < 3; ++a) {
    if (ray.dir[a] == 0) {
      if (ray.origin[a] < lo[a] || ray.origin[a] > hi[a]) return {0, 0, 0, 0};
      continue;
    }
    double ta = (lo[a] - ray.origin[a]) / ray.dir[a], tb = (hi[a] - ray.origin[a]) / ray.dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  // SPEC §12 "clip", on its own terms: kept where n . p + d >= 0 for each
  // plane (the crossing t = -(n . o + d) / (n . dir)) and inside the box.
  const ClipRegion& clip = v.clip_region();
  for (const ClipPlane& p : clip.planes) {
    const double along = p.normal.x * ray.dir.x + p.normal.y * ray.dir.y + p.normal.z * ray.dir.z;
    const double height = p.normal.x * ray.origin.x + p.normal.y * ray.origin.y + p.normal.z * ray.origin.z + p.d;
    if (along == 0) {
      if (height < 0) return {0, 0, 0, 0};
      continue;
    }
    const double t = -height / along;
    if (along > 0) {
      t0 = std::max(t0, t);
    } else {
      t1 = std::min(t1, t);
    }
  }
  if (clip.box)
    for (int a = 0; a < 3; ++a) {
      if (ray.dir[a] == 0) {
        if (ray.origin[a] < clip.box->lo[a] || ray.origin[a] > clip.box->hi[a]) return {0, 0, 0, 0};
        continue;
      }
      double ta = (clip.box->lo[a] - ray.origin[a]) / ray.dir[a], tb = (clip.box->hi[a] - ray.origin[a]) / ray.dir[a];
      if (ta > tb) std::swap(ta, tb);
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
    }
  if (!(t1 > t0)) return {0, 0, 0, 0};
  const double unit = std::min({v.spacing().x, v.spacing().y, v.spacing().z});
  const int n = std::clamp(int(std::ceil((t1 - t0) / (kReferenceStep * unit))), 1, 200000);
  const double h = (t1 - t0) / n;
  // Between two samples the scalar is taken as linear once the sample
  // between them lies within kLinear of the range of the line's value:
  // otherwise the interval is halved (to a 1e-6 of a voxel).
  const double kLinear = 1e-7 * std::max(1.0, double(v.max_value()) - v.min_value());
  State st;
  std::vector<double> cuts;
  // The scalar linear from s0 to s1 over len: cut where it crosses a point.
  auto add_linear = [&](double s0, double s1, double len) {
    if (s0 == s1) {
      const Values c = tf.above(s0);
      add_linear_piece(c, c, len, st);
      return;
    }
    const bool up = s1 > s0;
    tf.between(std::min(s0, s1), std::max(s0, s1), cuts);
    if (!up) std::reverse(cuts.begin(), cuts.end());
    double s = s0, done = 0;
    // Going up, a piece starting at a point takes its value from above, and
    // ends with its value from below; going down, the other way round.
    auto start = [&](double x) { return up ? tf.above(x) : tf.below(x); };
    auto finish = [&](double x) { return up ? tf.below(x) : tf.above(x); };
    for (double c : cuts) {
      const double l = len * (c - s0) / (s1 - s0) - done;
      add_linear_piece(start(s), finish(c), l, st);
      done += l;
      s = c;
    }
    add_linear_piece(start(s), finish(s1), len - done, st);
  };
  auto interval = [&](auto& self, double ta, double tb, double sa, double sb) -> void {
    const double tm = 0.5 * (ta + tb), sm = trilinear(v, ray.at(tm));
    if (std::abs(sm - 0.5 * (sa + sb)) <= kLinear || tb - ta < 1e-6 * unit) return add_linear(sa, sb, tb - ta);
    self(self, ta, tm, sa, sm);
    self(self, tm, tb, sm, sb);
  };
  double s_prev = trilinear(v, ray.at(t0));
  for (int k = 1; k <= n && st.T > 0; ++k) {
    const double s_next = trilinear(v, ray.at(t0 + k * h));
    interval(interval, t0 + (k - 1) * h, t0 + k * h, s_prev, s_next);
    s_prev = s_next;
  }
  return {st.C[0], st.C[1], st.C[2], 1 - st.T};
}

}  // namespace

Image reference_image(const Scene& scene) {
  const GridVolume& v = scene.grid();
  const Tf tf(scene.transfer_function.points());
  const Camera camera(scene.camera);
  Image image(camera.width(), camera.height());
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) image.set(x, y, integrate(v, tf, camera.ray(x, y)));
  return image;
}

}  // namespace vri::verify
