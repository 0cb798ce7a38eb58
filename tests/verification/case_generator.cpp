#include "verification/case_generator.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

#include "volume/builtin_volumes.hpp"

namespace vri::verify {

namespace {

using nlohmann::json;

// SplitMix64 over a counter: the same numbers everywhere (no std::
// distribution, whose output differs between standard libraries).
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed * 0x9e3779b97f4a7c15ull + 0x632be59bd9b4e019ull) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform(double lo = 0, double hi = 1) { return lo + (hi - lo) * double(next() >> 11) * 0x1p-53; }
  int integer(int lo, int hi) { return lo + int(next() % std::uint64_t(hi - lo + 1)); }  // [lo, hi]
  bool chance(double p) { return uniform() < p; }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

 private:
  std::uint64_t state_;
};

struct Made {
  GridVolume volume;
  json description;
  std::string family;
};

Made make_volume(Random& r) {
  const int kind = r.integer(0, 3);
  std::array<int, 3> dims{r.integer(2, 14), r.integer(2, 14), r.integer(2, 14)};
  Made m{GridVolume({2, 2, 2}, std::vector<float>(8, 0.f)), {}, ""};
  if (kind == 0) {
    const std::uint64_t seed = r.next() % 100000;
    m = {random_field(dims, seed), {{"builtin", "random"}, {"dims", dims}, {"seed", seed}}, "volume:random"};
  } else if (kind == 1) {
    dims = {r.integer(4, 18), r.integer(4, 18), r.integer(4, 18)};
    m = {sphere_distance(dims), {{"builtin", "sphere"}, {"dims", dims}}, "volume:sphere"};
  } else if (kind == 2) {
    const int n = r.integer(7, 19);
    dims = {n, n, n};
    m = {marschner_lobb(dims), {{"builtin", "marschner_lobb"}, {"dims", dims}}, "volume:marschner-lobb"};
  } else {  // two slices thin
    dims = {r.integer(3, 14), r.integer(3, 14), 2};
    const std::uint64_t seed = r.next() % 100000;
    m = {random_field(dims, seed), {{"builtin", "random"}, {"dims", dims}, {"seed", seed}}, "volume:thin"};
  }
  if (r.chance(0.5)) {  // uneven spacing and an origin away from 0
    const Vec3 spacing{r.uniform(0.3, 3), r.uniform(0.3, 3), r.uniform(0.3, 3)};
    Vec3 origin{r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-5, 5)};
    // One in ten of these far from the world's origin (to ~1.25e6): the
    // GPU's double-float rays and the CPU's double ones must still sample
    // alike there (issue 47, camera_rays.glsl). Drawn from the draws above,
    // so the other cases keep their seeds' scenes.
    if (origin.x > 4) {
      origin = origin * 2.5e5;
      m.family += "-far";
    }
    m.volume.set_spacing(spacing);
    m.volume.set_origin(origin);
    m.description["spacing"] = {spacing.x, spacing.y, spacing.z};
    m.description["origin"] = {origin.x, origin.y, origin.z};
  }
  return m;
}

// Extinctions in [0, 1] shaped by the grammar, scaled by the extinction family after.
struct TfMade {
  std::vector<ControlPoint> points;
  std::string family;
};

TfMade make_tf_shape(Random& r, double lo, double hi) {
  const double w = hi > lo ? hi - lo : 1;
  auto colour = [&](double s, double tau) { return ControlPoint{s, r.uniform(), r.uniform(), r.uniform(), tau}; };
  auto sorted_points = [&](int n, double a, double b) {
    std::vector<double> s;
    for (int i = 0; i < n; ++i) s.push_back(r.uniform(a, b));
    std::sort(s.begin(), s.end());
    std::vector<ControlPoint> p;
    for (double x : s) p.push_back(colour(x, r.uniform()));
    return p;
  };
  TfMade t;
  switch (r.integer(0, 7)) {
    case 0:
      t = {sorted_points(r.integer(2, 8), lo - 0.1 * w, hi + 0.1 * w), "tf:ramp"};
      break;
    case 1: {  // "transparent below s0": a step at the first point
      t = {sorted_points(r.integer(2, 6), lo + 0.05 * w, hi), "tf:first-step"};
      ControlPoint below = t.points.front();
      below.tau = 0;
      t.points.insert(t.points.begin(), below);
      break;
    }
    case 2: {  // a step at the last point
      t = {sorted_points(r.integer(2, 6), lo, hi - 0.05 * w), "tf:last-step"};
      ControlPoint above = colour(t.points.back().s, r.uniform());
      t.points.push_back(above);
      break;
    }
    case 3: {  // every point at one scalar
      const double s = r.uniform(lo, hi);
      for (int i = r.integer(2, 4); i > 0; --i) t.points.push_back(colour(s, r.uniform()));
      t.family = "tf:one-scalar";
      break;
    }
    case 4: {  // coincident and near-coincident points
      t = {sorted_points(r.integer(3, 8), lo, hi), "tf:coincident"};
      for (std::size_t i = 1; i < t.points.size(); ++i)
        if (r.chance(0.5)) t.points[i].s = t.points[i - 1].s + (r.chance(0.5) ? 0.0 : w * r.log_uniform(1e-15, 1e-6));
      break;
    }
    case 5: {  // spikes down to 1e-3 scalar units wide on a clear (or faint) ground
      t.family = "tf:spike";
      const double ground = r.chance(0.5) ? 0 : r.uniform(0, 0.05);
      std::vector<double> centres;
      for (int k = r.integer(1, 3); k > 0; --k) centres.push_back(r.uniform(lo, hi));
      std::sort(centres.begin(), centres.end());
      t.points.push_back(colour(lo - 0.01 * w, ground));
      double last = lo - 0.01 * w;
      for (double c : centres) {
        const double half = 0.5 * r.log_uniform(1e-3, std::max(2e-3, 0.2 * w));
        if (c - half <= last) continue;
        t.points.push_back(colour(c - half, ground));
        t.points.push_back(colour(c, 1));
        t.points.push_back(colour(c + half, ground));
        last = c + half;
      }
      t.points.push_back(colour(std::max(last, hi) + 0.01 * w, ground));
      break;
    }
    case 6:
      t = {sorted_points(r.integer(50, 500), lo, hi), "tf:many-points"};
      break;
    default: {  // colour changes where the extinction is zero or tiny
      t = {sorted_points(r.integer(4, 10), lo, hi), "tf:colour-at-zero-opacity"};
      for (auto& p : t.points)
        if (r.chance(0.6)) p.tau = r.chance(0.5) ? 0 : 1e-9;
      break;
    }
  }
  return t;
}

std::string extinction_family(double scale) {
  if (scale < 1e-2) return "extinction:faint";
  if (scale < 1e2) return "extinction:ordinary";
  if (scale < 1e6) return "extinction:dense";
  return "extinction:extreme";
}

struct CameraMade {
  CameraSpec spec;
  std::string family;
};

CameraMade make_camera(Random& r, const GridVolume& v) {
  const Vec3 lo = v.box_lo(), hi = v.box_hi(), centre = 0.5 * (lo + hi);
  const double radius = 0.5 * length(hi - lo);
  auto random_dir = [&] {
    for (;;) {
      const Vec3 d{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
      if (const double l = length(d); l > 0.1 && l <= 1) return (1 / l) * d;
    }
  };
  auto inside = [&] {
    return Vec3{r.uniform(lo.x, hi.x), r.uniform(lo.y, hi.y), r.uniform(lo.z, hi.z)};
  };
  CameraMade c;
  c.spec.width = c.spec.height = kImageSide;
  c.spec.fov_y = r.uniform(15, 70);
  switch (r.integer(0, 3)) {
    case 0:
      c.spec.eye = centre + r.uniform(1.3, 4) * radius * random_dir();
      c.spec.target = centre + 0.2 * radius * random_dir();
      c.family = "camera:outside";
      break;
    case 1:
      c.spec.eye = inside();
      c.spec.target = c.spec.eye + random_dir();
      c.spec.fov_y = r.uniform(40, 100);
      c.family = "camera:inside";
      break;
    case 2: {  // the eye in the plane of a face, looking along it
      const int a = r.integer(0, 2);
      Vec3 eye = inside(), target = inside();
      const double face = r.chance(0.5) ? lo[a] : hi[a];
      eye[a] = target[a] = face;
      eye[(a + 1) % 3] = lo[(a + 1) % 3] - r.uniform(0.5, 2) * radius;
      c.spec.eye = eye;
      c.spec.target = target;
      c.family = "camera:grazing";
      break;
    }
    default: {  // orthographic along a grid axis, through grid lines
      const int a = r.integer(0, 2);
      Vec3 dir{0, 0, 0};
      dir[a] = r.chance(0.5) ? 1 : -1;
      c.spec.projection = Projection::Orthographic;
      c.spec.ortho_height = r.uniform(0.5, 2.5) * radius;
      c.spec.target = centre;
      c.spec.eye = centre - 3 * radius * dir;
      c.family = "camera:ortho-axis";
      break;
    }
  }
  // An up vector away from the view direction.
  const Vec3 view = c.spec.target - c.spec.eye;
  c.spec.up = std::abs(view.z) < 0.9 * length(view) ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
  return c;
}

struct ClipMade {
  ClipRegion region;
  std::string family;
};

// SPEC §12 "clip" (issue 50), drawn after the rest so that a seed keeps its
// volume, transfer function, camera and light: oblique planes through the
// volume, a plane on a grid plane (a cell face), a plane the view runs
// along (grazing), a crop box (corners on grid points or past the volume),
// or a box beside the volume (nothing kept).
ClipMade make_clip(Random& r, const GridVolume& v, const CameraSpec& camera) {
  const Vec3 lo = v.box_lo(), hi = v.box_hi();
  auto inside = [&] { return Vec3{r.uniform(lo.x, hi.x), r.uniform(lo.y, hi.y), r.uniform(lo.z, hi.z)}; };
  auto unit = [&] {
    for (;;) {
      const Vec3 d{r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(-1, 1)};
      if (const double l = length(d); l > 0.1 && l <= 1) return (1 / l) * d;
    }
  };
  auto through = [](Vec3 n, Vec3 p) { return ClipPlane{n, -dot(n, p)}; };
  auto grid_point = [&](int a) { return v.origin()[a] + r.integer(0, v.dims()[a] - 1) * v.spacing()[a]; };
  ClipMade c;
  if (!r.chance(0.35)) return {{}, "clip:none"};
  switch (r.integer(0, 4)) {
    case 0:
      for (int k = r.integer(1, 3); k > 0; --k) c.region.planes.push_back(through(unit(), inside()));
      c.family = "clip:planes";
      break;
    case 1: {
      const int a = r.integer(0, 2);
      Vec3 n{0, 0, 0};
      n[a] = r.chance(0.5) ? 1 : -1;
      Vec3 p = inside();
      p[a] = grid_point(a);
      c.region.planes.push_back(through(n, p));
      c.family = "clip:cell-face";
      break;
    }
    case 2: {  // the plane holds the view's direction: rays near the middle graze it
      const Vec3 view = camera.target - camera.eye;
      Vec3 n = cross(view, unit());
      if (!(length(n) > 0)) n = Vec3{0, 0, 1};
      c.region.planes.push_back(through((1 / length(n)) * n, camera.target));
      c.family = "clip:grazing";
      break;
    }
    case 3: {
      Box box{inside(), inside()};
      for (int a = 0; a < 3; ++a) {
        if (box.lo[a] > box.hi[a]) std::swap(box.lo[a], box.hi[a]);
        if (r.chance(0.3)) box.lo[a] = grid_point(a);
        if (r.chance(0.2)) box.hi[a] = hi[a] + r.uniform(0, 1) * (hi[a] - lo[a]);
        if (box.lo[a] > box.hi[a]) std::swap(box.lo[a], box.hi[a]);
      }
      c.region.box = box;
      c.family = "clip:box";
      break;
    }
    default: {
      const Vec3 size = hi - lo;
      c.region.box = Box{hi + 0.1 * size, hi + 0.5 * size};
      c.family = "clip:nothing-kept";
      break;
    }
  }
  return c;
}

json clip_json(const ClipRegion& clip) {
  json out = json::object();
  if (!clip.planes.empty()) {
    out["planes"] = json::array();
    for (const ClipPlane& p : clip.planes) out["planes"].push_back({p.normal.x, p.normal.y, p.normal.z, p.d});
  }
  if (clip.box)
    out["box"] = {{clip.box->lo.x, clip.box->lo.y, clip.box->lo.z}, {clip.box->hi.x, clip.box->hi.y, clip.box->hi.z}};
  return out;
}

json points_json(const std::vector<ControlPoint>& points) {
  json out = json::array();
  for (const auto& p : points) out.push_back({p.s, p.r, p.g, p.b, p.tau});
  return out;
}

}  // namespace

Case make_case(std::uint64_t seed) {
  Random r(seed);
  Made volume = make_volume(r);
  const double lo = volume.volume.min_value(), hi = volume.volume.max_value();
  TfMade tf = make_tf_shape(r, lo, hi);
  const double scale = r.log_uniform(1e-6, 1e15);
  for (auto& p : tf.points) p.tau *= scale;
  CameraMade camera = make_camera(r, volume.volume);
  Lighting light;
  if (r.chance(0.3)) {
    light.enabled = true;
    light.ambient = r.uniform(0, 0.5);
    light.diffuse = r.uniform(0, 1);
    light.specular = r.uniform(0, 1);
    light.shininess = r.log_uniform(1, 1e3);
    light.mode = r.chance(0.5) ? "sampled" : "interpolated";
  }
  const ClipMade clip = make_clip(r, volume.volume, camera.spec);
  volume.volume.set_clip(clip.region);
  Case c{seed,
         {volume.family, tf.family, extinction_family(scale), camera.family, light.enabled ? "light:on" : "light:off",
          clip.family},
         Scene{volume.volume, TransferFunction(tf.points), camera.spec, light, {0, 0, 0}, {}},
         ""};
  const CameraSpec& cs = camera.spec;
  json j = {{"volume", volume.description},
            {"transfer_function", {{"points", points_json(tf.points)}}},
            {"camera",
             {{"eye", {cs.eye.x, cs.eye.y, cs.eye.z}},
              {"target", {cs.target.x, cs.target.y, cs.target.z}},
              {"up", {cs.up.x, cs.up.y, cs.up.z}},
              {"width", cs.width},
              {"height", cs.height}}}};
  if (cs.projection == Projection::Orthographic) {
    j["camera"]["projection"] = "orthographic";
    j["camera"]["ortho_height"] = cs.ortho_height;
  } else {
    j["camera"]["fov_y"] = cs.fov_y;
  }
  if (light.enabled)
    j["lighting"] = {{"enabled", true},          {"ambient", light.ambient}, {"diffuse", light.diffuse},
                     {"specular", light.specular}, {"shininess", light.shininess}, {"mode", light.mode}};
  if (clip.region.active()) j["clip"] = clip_json(clip.region);
  c.json = j.dump();
  return c;
}

}  // namespace vri::verify
