// ParaView colour-map presets -> linear pieces (transfer/paraview_colormap.hpp).
// The colour spaces and the opacity curve are VTK's (vtkColorTransferFunction,
// vtkMath's colour conversions, vtkPiecewiseFunction::GetTable), written again
// here; tools/make_colormaps.py checks the same formulas against VTK and
// stores VTK's tables, which tests/transfer/paraview_colormap_test.cpp matches.
#include "transfer/paraview_colormap.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>

#include "core/json_support.hpp"
#include "vri/error.hpp"

namespace vri {

namespace {

using json = nlohmann::json;
using Rgb = std::array<double, 3>;

// --- VTK's colour conversions (vtkMath: sRGB, XYZ with D65, CIE Lab) ----------

Rgb rgb_to_lab(const Rgb& c) {
  double lin[3];
  for (int i = 0; i < 3; ++i) lin[i] = c[i] > 0.04045 ? std::pow((c[i] + 0.055) / 1.055, 2.4) : c[i] / 12.92;
  const double x = (lin[0] * 0.4124 + lin[1] * 0.3576 + lin[2] * 0.1805) / 0.9505;
  const double y = lin[0] * 0.2126 + lin[1] * 0.7152 + lin[2] * 0.0722;
  const double z = (lin[0] * 0.0193 + lin[1] * 0.1192 + lin[2] * 0.9505) / 1.089;
  const auto f = [](double v) { return v > 0.008856 ? std::cbrt(v) : 7.787 * v + 16.0 / 116.0; };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

Rgb lab_to_rgb(const Rgb& lab) {
  const double fy = (lab[0] + 16) / 116;
  const auto finv = [](double v) { return v * v * v > 0.008856 ? v * v * v : (v - 16.0 / 116.0) / 7.787; };
  const double x = 0.9505 * finv(lab[1] / 500 + fy), y = finv(fy), z = 1.089 * finv(fy - lab[2] / 200);
  Rgb c{x * 3.2406 + y * -1.5372 + z * -0.4986, x * -0.9689 + y * 1.8758 + z * 0.0415,
        x * 0.0557 + y * -0.2040 + z * 1.0570};
  for (double& e : c) e = e > 0.0031308 ? 1.055 * std::pow(e, 1 / 2.4) - 0.055 : 12.92 * e;
  // vtkMath's gamut clipping: scaled down when above 1, negatives to 0.
  const double top = std::max({c[0], c[1], c[2]});
  for (double& e : c) e = std::max(top > 1 ? e / top : e, 0.0);
  return c;
}

// Moreland's Msh (polar CIE Lab) and the diverging interpolation, as in vtkColorTransferFunction.
Rgb lab_to_msh(const Rgb& lab) {
  const double m = std::sqrt(lab[0] * lab[0] + lab[1] * lab[1] + lab[2] * lab[2]);
  const double s = m > 0.001 ? std::acos(lab[0] / m) : 0.0;
  const double h = s > 0.001 ? std::atan2(lab[2], lab[1]) : 0.0;
  return {m, s, h};
}

Rgb msh_to_lab(const Rgb& msh) {
  return {msh[0] * std::cos(msh[1]), msh[0] * std::sin(msh[1]) * std::cos(msh[2]),
          msh[0] * std::sin(msh[1]) * std::sin(msh[2])};
}

double angle_diff(double a, double b) {
  constexpr double pi = std::numbers::pi;
  double d = std::abs(a - b);
  while (d >= 2 * pi) d -= 2 * pi;
  return d > pi ? 2 * pi - d : d;
}

// A hue for an unsaturated end, so the hue turns smoothly towards it.
double adjust_hue(const Rgb& msh, double unsat_m) {
  if (msh[0] >= unsat_m - 0.1) return msh[2];
  const double spin = msh[1] * std::sqrt(unsat_m * unsat_m - msh[0] * msh[0]) / (msh[0] * std::sin(msh[1]));
  return msh[2] > -0.3 * std::numbers::pi ? msh[2] + spin : msh[2] - spin;
}

Rgb diverging(double s, const Rgb& a, const Rgb& b) {
  Rgb m1 = lab_to_msh(rgb_to_lab(a)), m2 = lab_to_msh(rgb_to_lab(b));
  if (m1[1] > 0.05 && m2[1] > 0.05 && angle_diff(m1[2], m2[2]) > 0.33 * std::numbers::pi) {
    const double mid = std::max({m1[0], m2[0], 88.0});
    if (s < 0.5) {
      m2 = {mid, 0, 0};
      s = 2 * s;
    } else {
      m1 = {mid, 0, 0};
      s = 2 * s - 1;
    }
  }
  if (m1[1] < 0.05 && m2[1] > 0.05) m1[2] = adjust_hue(m2, m1[0]);
  else if (m2[1] < 0.05 && m1[1] > 0.05) m2[2] = adjust_hue(m1, m2[0]);
  Rgb m;
  for (int i = 0; i < 3; ++i) m[i] = (1 - s) * m1[i] + s * m2[i];
  return lab_to_rgb(msh_to_lab(m));
}

Rgb rgb_to_hsv(const Rgb& c) {
  const double hi = std::max({c[0], c[1], c[2]}), lo = std::min({c[0], c[1], c[2]});
  const double s = hi > 0 ? (hi - lo) / hi : 0.0;
  double h = 0;
  if (s > 0) {
    if (c[0] == hi) h = (c[1] - c[2]) / (hi - lo) / 6;
    else if (c[1] == hi) h = 1.0 / 3 + (c[2] - c[0]) / (hi - lo) / 6;
    else h = 2.0 / 3 + (c[0] - c[1]) / (hi - lo) / 6;
    if (h < 0) h += 1;
  }
  return {h, s, hi};
}

Rgb hsv_to_rgb(const Rgb& hsv) {
  const double h = hsv[0], s = hsv[1], v = hsv[2];
  Rgb c;
  if (h > 1.0 / 6 && h <= 1.0 / 3) c = {(1.0 / 3 - h) * 6, 1, 0};
  else if (h > 1.0 / 3 && h <= 0.5) c = {0, 1, (h - 1.0 / 3) * 6};
  else if (h > 0.5 && h <= 2.0 / 3) c = {0, (2.0 / 3 - h) * 6, 1};
  else if (h > 2.0 / 3 && h <= 5.0 / 6) c = {(h - 2.0 / 3) * 6, 0, 1};
  else if (h > 5.0 / 6 && h <= 1) c = {1, 0, (1 - h) * 6};
  else c = {1, h * 6, 0};
  for (double& e : c) e = (s * e + 1 - s) * v;
  return c;
}

Rgb clamped(Rgb c) {
  for (double& e : c) e = std::clamp(e, 0.0, 1.0);
  return c;
}

// --- reduction to linear pieces ------------------------------------------------

// Samples of a curve: x non-decreasing; two samples at one x are a jump.
struct Samples {
  std::vector<double> x;
  std::vector<Rgb> v;
  void add(double xi, const Rgb& vi) {
    x.push_back(xi);
    v.push_back(vi);
  }
};

// The indices kept: every run's ends (a run: samples between jumps) and, inside
// a run, as few samples as a galloping search finds such that `fits(i, j)`
// holds for each kept piece i..j (every sample between within tolerance).
std::vector<std::size_t> reduce(const Samples& s, const std::function<bool(std::size_t, std::size_t)>& fits) {
  std::vector<std::size_t> keep;
  const std::size_t n = s.x.size();
  std::size_t first = 0;
  while (first < n) {
    std::size_t last = first;
    while (last + 1 < n && s.x[last + 1] > s.x[last]) ++last;
    keep.push_back(first);
    for (std::size_t i = first; i < last;) {
      std::size_t good = i + 1, bad = 0, probe = 2;
      while (good < last) {
        const std::size_t j = std::min(last, i + probe);
        if (!fits(i, j)) {
          bad = j;
          break;
        }
        good = j;
        probe *= 2;
      }
      while (bad > good + 1) {
        const std::size_t mid = good + (bad - good) / 2;
        (fits(i, mid) ? good : bad) = mid;
      }
      keep.push_back(good);
      i = good;
    }
    first = last + 1;
  }
  return keep;
}

// At most this many samples in all, so a file of many nodes stays cheap.
constexpr std::size_t kMaxSamples = std::size_t{1} << 20;
// Halvings of a sample interval at most (1/4096 of it).
constexpr int kMaxDepth = 12;

// Samples f(t), t in (0, 1], onto x in (xa, xb]: `per` even steps, each halved
// while its midpoint lies off the chord by more than tolerance/8, so kinks (the
// gamut clipping of Lab, the sectors of HSV) and steep stretches (a sharp
// opacity curve) get samples close by. f(0) is the caller's.
class Sampler {
 public:
  Sampler(Samples& out, double tolerance) : out_(out), tol_(tolerance / 8) {}

  template <class F>
  void interval(double xa, double xb, std::size_t per, const F& f) {
    const auto x_of = [&](double t) { return t >= 1 ? xb : std::lerp(xa, xb, t); };  // no overflow at -+1e308
    Rgb v0 = f(0.0);
    for (std::size_t k = 1; k <= per; ++k) {
      const double t0 = double(k - 1) / double(per), t1 = double(k) / double(per);
      const Rgb v1 = f(t1);
      refine(t0, v0, t1, v1, 0, f, x_of);
      v0 = v1;
    }
  }

 private:
  template <class F, class X>
  void refine(double t0, const Rgb& v0, double t1, const Rgb& v1, int depth, const F& f, const X& x_of) {
    const double tm = 0.5 * (t0 + t1);
    const Rgb vm = f(tm);
    double off = 0;
    for (int c = 0; c < 3; ++c) off = std::max(off, std::abs(vm[c] - 0.5 * (v0[c] + v1[c])));
    if (off > tol_ && depth < kMaxDepth && out_.x.size() < kMaxSamples) {
      refine(t0, v0, tm, vm, depth + 1, f, x_of);
      refine(tm, vm, t1, v1, depth + 1, f, x_of);
      return;
    }
    out_.add(x_of(tm), vm);
    out_.add(x_of(t1), v1);
  }

  Samples& out_;
  double tol_;
};

std::size_t per_interval(std::size_t intervals, std::size_t most) {
  return std::clamp<std::size_t>(kMaxSamples / 16 / std::max<std::size_t>(intervals, 1), 1, most);
}

// --- reading the file ------------------------------------------------------------

// A flat array of numbers in groups of 4, each finite.
std::vector<std::array<double, 4>> quadruples(const json& p, const char* key, const std::string& where) {
  const json& a = p.at(key);
  if (!a.is_array() || a.empty())
    throw Error(where + key + ": expected a non-empty array of numbers, found " + found(a));
  if (a.size() % 4 != 0)
    throw Error(where + key + ": length " + std::to_string(a.size()) + " is not a multiple of 4 (x, " +
                (std::string(key) == "RGBPoints" ? "r, g, b" : "alpha, midpoint, sharpness") + " per point)");
  std::vector<std::array<double, 4>> out(a.size() / 4);
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!a[i].is_number() || !std::isfinite(a[i].get<double>()))
      throw Error(where + key + "[" + std::to_string(i) + "]: expected a finite number, found " + found(a[i]));
    out[i / 4][i % 4] = a[i].get<double>();
  }
  for (std::size_t i = 1; i < out.size(); ++i)
    if (out[i][0] < out[i - 1][0])
      throw Error(where + key + ": x must not decrease: point " + std::to_string(i) + " has x = " +
                  number_text(out[i][0]) + " after " + number_text(out[i - 1][0]));
  return out;
}

void check_unit(const std::string& where, const char* key, std::size_t point, double value, const char* what) {
  if (!(value >= 0 && value <= 1))
    throw Error(where + key + ": point " + std::to_string(point) + ": " + what + " " + number_text(value) +
                " is outside [0, 1]");
}

std::string preset_names(const json& presets) {
  std::string list;
  std::size_t shown = 0;
  for (const json& p : presets) {
    if (shown == 12) {
      list += ", and " + std::to_string(presets.size() - shown) + " more";
      break;
    }
    list += (shown++ ? ", '" : "'");
    list += p.is_object() && p.contains("Name") && p["Name"].is_string() ? printable(p["Name"].get<std::string>(), 60)
                                                                          : std::string("(unnamed)");
    list += "'";
  }
  return list;
}

}  // namespace

std::array<double, 3> interpolate_color(ColorSpace space, double s, const std::array<double, 3>& a,
                                        const std::array<double, 3>& b, bool hsv_wrap) {
  switch (space) {
    case ColorSpace::Rgb: return {(1 - s) * a[0] + s * b[0], (1 - s) * a[1] + s * b[1], (1 - s) * a[2] + s * b[2]};
    case ColorSpace::Step: return b;
    case ColorSpace::Lab: {
      const Rgb la = rgb_to_lab(a), lb = rgb_to_lab(b);
      return lab_to_rgb({(1 - s) * la[0] + s * lb[0], (1 - s) * la[1] + s * lb[1], (1 - s) * la[2] + s * lb[2]});
    }
    case ColorSpace::Diverging: return diverging(s, a, b);
    case ColorSpace::Hsv: {
      Rgb ha = rgb_to_hsv(a), hb = rgb_to_hsv(b);
      if (hsv_wrap && std::abs(ha[0] - hb[0]) > 0.5) (ha[0] > hb[0] ? ha[0] : hb[0]) -= 1;
      Rgb h{(1 - s) * ha[0] + s * hb[0], (1 - s) * ha[1] + s * hb[1], (1 - s) * ha[2] + s * hb[2]};
      if (h[0] < 0) h[0] += 1;
      return hsv_to_rgb(h);
    }
  }
  return a;
}

double opacity_curve(double s, double y1, double y2, double midpoint, double sharpness) {
  midpoint = std::clamp(midpoint, 0.00001, 0.99999);
  s = s < midpoint ? 0.5 * s / midpoint : 0.5 + 0.5 * (s - midpoint) / (1 - midpoint);
  if (sharpness > 0.99) return s < 0.5 ? y1 : y2;
  if (sharpness < 0.01) return (1 - s) * y1 + s * y2;
  if (s < 0.5) s = 0.5 * std::pow(2 * s, 1 + 10 * sharpness);
  else if (s > 0.5) s = 1 - 0.5 * std::pow(2 * (1 - s), 1 + 10 * sharpness);
  const double ss = s * s, sss = ss * s, t = (1 - sharpness) * (y2 - y1);
  const double y = (2 * sss - 3 * ss + 1) * y1 + (-2 * sss + 3 * ss) * y2 + (sss - 2 * ss + s) * t + (sss - ss) * t;
  return std::clamp(y, std::min(y1, y2), std::max(y1, y2));
}

ParaviewColormap parse_paraview_colormap(std::string_view text, const std::string& source, const std::string& name) {
  json j = parse_json(text, source);
  if (j.is_object()) j = json::array({j});
  if (!j.is_array() || j.empty())
    throw Error(source + ": expected a JSON array of ParaView colour-map presets, found " + found(j));
  const json* chosen = nullptr;
  if (name.empty()) {
    if (j.size() > 1)
      throw Error(source + ": holds " + std::to_string(j.size()) + " presets; say which with \"name\": " +
                  preset_names(j));
    chosen = &j[0];
  } else {
    for (const json& p : j)
      if (p.is_object() && p.contains("Name") && p["Name"] == name) {
        chosen = &p;
        break;
      }
    if (!chosen)
      throw Error(source + ": no preset named '" + printable(name, 60) + "' (it holds " + preset_names(j) + ")");
  }
  const json& p = *chosen;
  if (!p.is_object()) throw Error(source + ": a preset must be a JSON object, found " + found(p));
  ParaviewColormap map;
  if (p.contains("Name") && p["Name"].is_string()) map.name = p["Name"].get<std::string>();
  const std::string where = source + ": preset '" + printable(map.name, 60) + "': ";
  if (p.contains("IndexedColors"))
    throw Error(where + "IndexedColors: indexed (categorical) colour maps are not supported; vri reads RGBPoints");
  if (p.contains("UseLogScale") && p["UseLogScale"] != false && p["UseLogScale"] != 0)
    throw Error(where + "UseLogScale: log-scale colour maps are not supported");
  if (!p.contains("RGBPoints")) throw Error(where + "has no RGBPoints");
  if (p.contains("ColorSpace")) {
    const json& cs = p["ColorSpace"];
    const std::string s = cs.is_string() ? cs.get<std::string>() : "";
    if (s == "RGB") map.color_space = ColorSpace::Rgb;
    else if (s == "HSV") map.color_space = ColorSpace::Hsv;
    else if (s == "Lab" || s == "CIELAB") map.color_space = ColorSpace::Lab;
    else if (s == "Diverging") map.color_space = ColorSpace::Diverging;
    else if (s == "Step") map.color_space = ColorSpace::Step;
    else
      throw Error(where + "ColorSpace: expected RGB, HSV, Lab, CIELAB, Diverging or Step, found " + found(cs) +
                  (s == "Lab/CIEDE2000" ? " (not supported)" : ""));
  }
  if (p.contains("HSVWrap")) {
    const json& w = p["HSVWrap"];
    if (w.is_boolean()) map.hsv_wrap = w.get<bool>();
    else if (w.is_number() && (w == 0 || w == 1)) map.hsv_wrap = w == 1;
    else throw Error(where + "HSVWrap: expected 0 or 1, found " + found(w));
  }
  const auto rgb = quadruples(p, "RGBPoints", where);
  for (std::size_t i = 0; i < rgb.size(); ++i) {
    for (int c = 1; c < 4; ++c) check_unit(where, "RGBPoints", i, rgb[i][c], "colour component");
    map.rgb_points.push_back({rgb[i][0], rgb[i][1], rgb[i][2], rgb[i][3]});
  }
  if (p.contains("Points")) {
    const auto pts = quadruples(p, "Points", where);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      check_unit(where, "Points", i, pts[i][1], "alpha");
      check_unit(where, "Points", i, pts[i][2], "midpoint");
      check_unit(where, "Points", i, pts[i][3], "sharpness");
      map.opacity.push_back({pts[i][0], pts[i][1], pts[i][2], pts[i][3]});
    }
  }
  return map;
}

std::vector<ColormapPoint> linear_colors(const ParaviewColormap& map, double tolerance) {
  const auto& pts = map.rgb_points;
  const auto rgb = [](const ColormapPoint& p) { return Rgb{p.r, p.g, p.b}; };
  const bool rgb_space = map.color_space == ColorSpace::Rgb;
  const std::size_t per = rgb_space ? 1 : per_interval(pts.size(), 16);
  Samples s;
  Sampler sampler(s, tolerance);
  s.add(pts[0].x, rgb(pts[0]));
  std::size_t reached = 0;  // the node the samples end at
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const ColormapPoint &a = pts[i], &b = pts[i + 1];
    if (!(b.x > a.x)) continue;  // two nodes at one x: the jump is taken below
    if (map.color_space == ColorSpace::Step) {  // b's colour on (a.x, b.x]
      s.add(a.x, rgb(b));
      s.add(b.x, rgb(b));
    } else {
      const auto f = [&](double t) {
        return clamped(interpolate_color(map.color_space, t, rgb(a), rgb(b), map.hsv_wrap));
      };
      if (reached != i) s.add(a.x, f(0));
      if (rgb_space) s.add(b.x, f(1));
      else sampler.interval(a.x, b.x, per, f);
    }
    reached = i + 1;
  }
  if (reached + 1 < pts.size()) s.add(pts.back().x, rgb(pts.back()));  // trailing nodes at one x: a last jump
  const auto fits = [&](std::size_t i, std::size_t j) {
    for (std::size_t k = i + 1; k < j; ++k) {
      const double t = (s.x[k] - s.x[i]) / (s.x[j] - s.x[i]);
      for (int c = 0; c < 3; ++c)
        if (!(std::abs(s.v[i][c] + t * (s.v[j][c] - s.v[i][c]) - s.v[k][c]) < tolerance)) return false;
    }
    return true;
  };
  std::vector<ColormapPoint> out;
  for (const std::size_t k : reduce(s, fits)) out.push_back({s.x[k], s.v[k][0], s.v[k][1], s.v[k][2]});
  return out;
}

std::vector<TauPoint> linear_opacity(const std::vector<OpacityNode>& given, double tolerance) {
  std::vector<OpacityNode> nodes = given;  // alpha 1 (opaque at any distance) as the largest below it
  for (OpacityNode& n : nodes) n.alpha = std::min(n.alpha, kOpaqueAlpha);
  const std::size_t per = per_interval(nodes.size(), 32);
  Samples s;  // v[0]: alpha
  Sampler sampler(s, tolerance);
  s.add(nodes[0].x, {nodes[0].alpha, 0, 0});
  std::size_t reached = 0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const OpacityNode &a = nodes[i], &b = nodes[i + 1];
    if (!(b.x > a.x)) continue;
    if (reached != i) s.add(a.x, {a.alpha, 0, 0});
    if (a.sharpness > 0.99) {  // VTK's step where the midpoint falls
      const double mid = a.x + std::clamp(a.midpoint, 0.00001, 0.99999) * (b.x - a.x);
      s.add(mid, {a.alpha, 0, 0});
      s.add(mid, {b.alpha, 0, 0});
      s.add(b.x, {b.alpha, 0, 0});
    } else {
      sampler.interval(a.x, b.x, a.alpha == b.alpha ? 1 : per, [&](double t) {
        return Rgb{opacity_curve(t, a.alpha, b.alpha, a.midpoint, a.sharpness), 0, 0};
      });
    }
    reached = i + 1;
  }
  if (reached + 1 < nodes.size()) s.add(nodes.back().x, {nodes.back().alpha, 0, 0});
  std::vector<double> tau(s.x.size());
  for (std::size_t k = 0; k < tau.size(); ++k) tau[k] = -std::log1p(-s.v[k][0]);
  const auto fits = [&](std::size_t i, std::size_t j) {
    for (std::size_t k = i + 1; k < j; ++k) {
      const double t = (s.x[k] - s.x[i]) / (s.x[j] - s.x[i]);
      const double alpha = -std::expm1(-(tau[i] + t * (tau[j] - tau[i])));
      if (!(std::abs(alpha - s.v[k][0]) < tolerance)) return false;
    }
    return true;
  };
  std::vector<TauPoint> out;
  for (const std::size_t k : reduce(s, fits)) out.push_back({s.x[k], tau[k]});
  return out;
}

}  // namespace vri
