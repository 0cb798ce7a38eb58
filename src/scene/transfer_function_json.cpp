// The transfer-function forms (transfer_function_json.hpp; docs/SCENES.md,
// "Transfer functions"): read and checked first, spread over their range when
// the volume is known.
#include "scene/transfer_function_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>
#include <utility>

#include "core/json_support.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "scene/value_range.hpp"

namespace vri {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

using Rgb = std::array<double, 3>;

// Where x lies in [x0, x1], in [0, 1]; 0 when the span is empty. In halves
// where the span overflows (x near -+1e308).
double fraction(double x, double x0, double x1) {
  if (!(x1 > x0)) return 0;
  double t = (x - x0) / (x1 - x0);
  if (!std::isfinite(t)) t = (0.5 * x - 0.5 * x0) / (0.5 * x1 - 0.5 * x0);
  return std::clamp(t, 0.0, 1.0);
}

// A range of one value (a constant volume) is widened upwards, so the transfer
// function still has an extent; downwards where that would overflow.
ValueRange widened(ValueRange r) {
  if (r.lo < r.hi) return r;
  const double w = std::max(std::abs(r.lo), 1.0) * TransferFunctionRequest::kWiden;
  if (std::isfinite(r.lo + w)) return {r.lo, r.lo + w};
  return {r.lo - w, r.lo};
}

// The values of a piecewise-linear function at s, from below and from above
// (different only where it steps at s); end values held outside.
template <class V, class Mix>
std::pair<V, V> sides(const std::vector<std::pair<double, V>>& f, double s, Mix mix) {
  auto lo = std::lower_bound(f.begin(), f.end(), s, [](const auto& p, double v) { return p.first < v; });
  if (lo != f.end() && lo->first == s) {
    auto hi = lo;
    while (hi + 1 != f.end() && (hi + 1)->first == s) ++hi;
    return {lo->second, hi->second};
  }
  if (lo == f.begin()) return {f.front().second, f.front().second};
  if (lo == f.end()) return {f.back().second, f.back().second};
  const V v = mix(lo[-1].second, lo->second, fraction(s, lo[-1].first, lo->first));
  return {v, v};
}

// Colours and extinction on breakpoints of their own -> control points on the
// union of both (each interpolated at the other's breakpoints).
TransferFunction merged(const std::vector<std::pair<double, Rgb>>& colors,
                        const std::vector<std::pair<double, double>>& taus) {
  std::vector<double> at;
  for (const auto& c : colors) at.push_back(c.first);
  for (const auto& t : taus) at.push_back(t.first);
  std::sort(at.begin(), at.end());
  at.erase(std::unique(at.begin(), at.end()), at.end());
  const auto mix_rgb = [](const Rgb& a, const Rgb& b, double t) {
    return Rgb{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
  };
  const auto mix_tau = [](double a, double b, double t) { return a + t * (b - a); };
  const auto point = [](double s, const Rgb& c, double tau) {
    return ControlPoint{s, std::clamp(c[0], 0.0, 1.0), std::clamp(c[1], 0.0, 1.0), std::clamp(c[2], 0.0, 1.0),
                        std::max(tau, 0.0)};
  };
  std::vector<ControlPoint> points;
  for (const double s : at) {
    const auto [c_lo, c_hi] = sides(colors, s, mix_rgb);
    const auto [t_lo, t_hi] = sides(taus, s, mix_tau);
    points.push_back(point(s, c_lo, t_lo));
    if (c_lo != c_hi || t_lo != t_hi) points.push_back(point(s, c_hi, t_hi));
  }
  return TransferFunction(std::move(points));
}

constexpr std::array<std::string_view, 9> kKeys = {"points", "opacity_points", "unit_distance", "colormap", "paraview",
                                                   "name",   "opacity",        "range",         "file"};

}  // namespace

std::string TransferFunctionRequest::ctx() const { return path_.empty() ? file_ : file_ + ": " + path_; }

std::string TransferFunctionRequest::where(const std::string& key) const {
  return file_ + ": " + (path_.empty() ? key : path_ + "." + key);
}

TransferFunctionRequest::TransferFunctionRequest(const json& j, std::string file, std::string path, fs::path base,
                                                 bool may_name_file)
    : file_(std::move(file)), path_(std::move(path)) {
  if (!j.is_object()) throw Error(ctx() + ": expected a JSON object, found " + found(j));
  const std::span<const std::string_view> keys(kKeys.data(), kKeys.size() - (may_name_file ? 0 : 1));
  for (const auto& item : j.items())
    if (std::find(keys.begin(), keys.end(), item.key()) == keys.end())
      throw Error(where(printable(item.key(), 40)) + ": unknown key" + key_suggestion(item.key(), keys));
  std::vector<std::string> forms;
  for (const char* f : {"points", "opacity_points", "colormap", "paraview"})
    if (j.contains(f)) forms.emplace_back(f);
  if (forms.empty()) throw Error(ctx() + ": needs 'points', 'opacity_points', 'colormap' or 'paraview'");
  if (forms.size() > 1)
    throw Error(ctx() + ": give one of 'points', 'opacity_points', 'colormap' and 'paraview', not both '" + forms[0] +
                "' and '" + forms[1] + "'");
  const std::string& form = forms[0];
  const bool points_form = form == "points" || form == "opacity_points";
  if (j.contains("name") && form != "paraview") throw Error(where("name") + ": applies to 'paraview' only");
  if (j.contains("opacity") && points_form)
    throw Error(where("opacity") + ": applies to 'colormap' and 'paraview' (" + form + " carry their own)");
  if (j.contains("unit_distance") && form != "opacity_points" && !j.contains("opacity"))
    throw Error(where("unit_distance") + ": applies to 'opacity_points' and 'opacity'");
  const auto string_at = [&](const char* key) {
    if (!j.at(key).is_string()) throw Error(where(key) + ": expected a string, found " + found(j.at(key)));
    return j.at(key).get<std::string>();
  };
  range_ = read_range(j);

  if (points_form) {
    form_ = Form::Points;
    const json& a = j.at(form);
    if (!a.is_array() || a.empty()) throw Error(where(form) + ": expected a non-empty array, found " + found(a));
    std::vector<std::array<double, 5>> rows;
    for (std::size_t i = 0; i < a.size(); ++i) {
      const json& row = a[i];
      const bool ok = row.is_array() && row.size() == 5 &&
                      std::all_of(row.begin(), row.end(), [](const json& e) {
                        return e.is_number() && std::isfinite(e.get<double>());
                      });
      if (!ok)
        throw Error(where(form + "[" + std::to_string(i) + "]") + ": expected an array of 5 finite numbers, found " +
                    found(row));
      rows.push_back({row[0].get<double>(), row[1].get<double>(), row[2].get<double>(), row[3].get<double>(),
                      row[4].get<double>()});
    }
    try {
      if (form == "points") {
        std::vector<ControlPoint> cps;
        for (const auto& p : rows) cps.push_back({p[0], p[1], p[2], p[3], p[4]});
        points_ = TransferFunction(std::move(cps)).points();
      } else {
        if (!j.contains("unit_distance")) throw Error(ctx() + ": missing 'unit_distance'");
        const json& u = j.at("unit_distance");
        if (!u.is_number() || !std::isfinite(u.get<double>()))
          throw Error(where("unit_distance") + ": expected a finite number, found " + found(u));
        std::vector<TransferFunction::OpacityPoint> ops;
        for (const auto& p : rows) ops.push_back({p[0], p[1], p[2], p[3], p[4]});
        points_ = TransferFunction::from_opacity(ops, u.get<double>()).points();
      }
    } catch (const Error& e) {
      const std::string msg = e.what();
      if (msg.rfind(file_, 0) == 0) throw;
      throw Error(ctx() + ": " + msg);
    }
    return;
  }

  if (form == "colormap") {
    form_ = Form::Colormap;
    const std::string name = string_at("colormap");
    const Colormap* map = find_colormap(name);
    if (!map) {
      std::string known;
      for (const auto& n : colormap_names()) known += (known.empty() ? "" : ", ") + n;
      throw Error(where("colormap") + ": unknown colour map '" + printable(name, 40) + "' (known: " + known + ")");
    }
    colors_.assign(map->points.begin(), map->points.end());
    if (!range_) range_ = Range{Range::Kind::Data, 0, 0, true};
  } else {
    form_ = Form::Paraview;
    fs::path file = string_at("paraview");
    if (file.is_relative()) file = base / file;
    const std::string name = j.contains("name") ? string_at("name") : std::string();
    ParaviewColormap map;
    try {
      map = parse_paraview_colormap(text_of(file), "ParaView colour map '" + printable(file.string()) + "'", name);
    } catch (const FileError& e) {
      throw FileError(where("paraview") + ": " + e.what());
    } catch (const Error& e) {
      throw Error(where("paraview") + ": " + e.what());
    }
    colors_ = linear_colors(map);
    if (!j.contains("opacity") && !map.opacity.empty()) {
      try {
        opacity_ = linear_opacity(map.opacity);
      } catch (const Error& e) {
        throw Error(where("paraview") + ": ParaView colour map '" + printable(file.string()) + "': preset '" +
                    printable(map.name, 60) + "': Points: " + e.what() + " (or give \"opacity\")");
      }
      opacity_relative_ = false;
    }
  }
  if (j.contains("opacity")) opacity_ = read_opacity(j);
  else if (opacity_.empty()) opacity_ = {{0, 0}, {1, 1}};  // the default ramp, tau 0 -> 1 over the range
}

std::optional<TransferFunctionRequest::Range> TransferFunctionRequest::read_range(const json& j) const {
  if (!j.contains("range")) return std::nullopt;
  const json& v = j.at("range");
  const auto pair = [&](const json& a, const std::string& key) {
    const bool ok = a.is_array() && a.size() == 2 && a[0].is_number() && a[1].is_number() &&
                    std::isfinite(a[0].get<double>()) && std::isfinite(a[1].get<double>());
    if (!ok) throw Error(where(key) + ": expected an array of 2 finite numbers, found " + found(a));
    return std::pair{a[0].get<double>(), a[1].get<double>()};
  };
  if (v.is_string() && v == "data") return Range{Range::Kind::Data};
  if (v.is_array()) {
    const auto [lo, hi] = pair(v, "range");
    if (lo > hi) throw Error(where("range") + ": lo " + number_text(lo) + " is above hi " + number_text(hi));
    return Range{Range::Kind::Given, lo, hi};
  }
  if (v.is_object() && v.contains("percentiles")) {
    for (const auto& item : v.items())
      if (item.key() != "percentiles")
        throw Error(where("range." + printable(item.key(), 40)) + ": unknown key (known: percentiles)");
    const auto [lo, hi] = pair(v.at("percentiles"), "range.percentiles");
    if (!(lo >= 0 && lo <= hi && hi <= 100))
      throw Error(where("range.percentiles") + ": expected 0 <= p_lo <= p_hi <= 100, found " +
                  found(v.at("percentiles")));
    return Range{Range::Kind::Percentiles, lo, hi};
  }
  throw Error(where("range") + ": expected [lo, hi], \"data\" or {\"percentiles\": [p_lo, p_hi]}, found " + found(v));
}

std::vector<TauPoint> TransferFunctionRequest::read_opacity(const json& j) const {
  const json& a = j.at("opacity");
  if (!a.is_array() || a.empty())
    throw Error(where("opacity") + ": expected a non-empty array of [x, value], found " + found(a));
  double unit = 0;  // > 0: the values are alpha at this unit distance
  if (j.contains("unit_distance")) {
    const json& u = j.at("unit_distance");
    if (!u.is_number() || !(u.get<double>() > 0) || !std::isfinite(u.get<double>()))
      throw Error(where("unit_distance") + ": expected a finite number > 0, found " + found(u));
    unit = u.get<double>();
  }
  std::vector<TauPoint> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string key = "opacity[" + std::to_string(i) + "]";
    const json& row = a[i];
    const bool ok = row.is_array() && row.size() == 2 && row[0].is_number() && row[1].is_number() &&
                    std::isfinite(row[0].get<double>()) && std::isfinite(row[1].get<double>());
    if (!ok) throw Error(where(key) + ": expected an array of 2 finite numbers [x, value], found " + found(row));
    const double x = row[0].get<double>(), v = row[1].get<double>();
    if (!(x >= 0 && x <= 1))
      throw Error(where(key) + ": x = " + number_text(x) + " is outside [0, 1] (a fraction of the range)");
    if (!out.empty() && x < out.back().x)
      throw Error(where(key) + ": x = " + number_text(x) + " is below the previous " + number_text(out.back().x) +
                  " (points must be sorted by x)");
    if (unit > 0) {
      if (!(v >= 0 && v < 1))
        throw Error(where(key) + ": alpha must be in [0, 1) (1 is opaque at any distance), got " + number_text(v));
      out.push_back({x, -std::log1p(-v) / unit});
    } else {
      if (!(v >= 0)) throw Error(where(key) + ": tau must be >= 0, got " + number_text(v));
      out.push_back({x, v});
    }
  }
  return out;
}

bool TransferFunctionRequest::needs_volume() const { return range_ && range_->kind != Range::Kind::Given; }

TransferFunction TransferFunctionRequest::resolve(const Volume* volume) const {
  std::optional<ValueRange> range;
  if (range_) {
    if (range_->kind == Range::Kind::Given) {
      range = ValueRange{range_->a, range_->b};
    } else if (!volume) {
      if (range_->implicit)
        throw Error(where("colormap") + ": without 'range' it spans the volume's data (\"range\": \"data\"), which "
                                        "needs a volume; give \"range\": [lo, hi]");
      throw Error(where("range") + ": " +
                  (range_->kind == Range::Kind::Data ? "\"data\"" : "{\"percentiles\": ...}") +
                  " needs a volume; give [lo, hi]");
    } else {
      try {
        range = range_->kind == Range::Kind::Data ? data_range(*volume)
                                                  : percentile_range(*volume, range_->a, range_->b);
      } catch (const Error& e) {
        throw Error(where("range") + ": " + e.what());
      }
    }
  }
  try {
    if (form_ == Form::Points) {
      if (!range) return TransferFunction(points_);
      const ValueRange r = widened(*range);
      std::vector<ControlPoint> points = points_;
      for (ControlPoint& p : points) p.s = std::lerp(r.lo, r.hi, fraction(p.s, points_.front().s, points_.back().s));
      return TransferFunction(std::move(points));
    }
    // Colour maps: fractions of the range. ParaView: the file's x, moved onto
    // the range when one is given; without, "opacity" and the default ramp
    // span the file's RGBPoints.
    const ValueRange r = widened(range ? *range : ValueRange{colors_.front().x, colors_.back().x});
    const auto place = [&](double x, bool relative, double x0, double x1) {
      if (relative) return std::lerp(r.lo, r.hi, x);
      return range ? std::lerp(r.lo, r.hi, fraction(x, x0, x1)) : x;
    };
    std::vector<std::pair<double, Rgb>> colors;
    for (const ColormapPoint& c : colors_)
      colors.push_back({place(c.x, form_ == Form::Colormap, colors_.front().x, colors_.back().x), {c.r, c.g, c.b}});
    std::vector<std::pair<double, double>> taus;
    for (const TauPoint& t : opacity_)
      taus.push_back({place(t.x, opacity_relative_, opacity_.front().x, opacity_.back().x), t.tau});
    return merged(colors, taus);
  } catch (const Error& e) {
    const std::string msg = e.what();
    if (msg.rfind(file_, 0) == 0) throw;
    throw Error(ctx() + ": " + msg);
  }
}

TransferFunctionRequest transfer_function_request(const fs::path& path) {
  const std::string source = "transfer function '" + printable(path.string()) + "'";
  return TransferFunctionRequest(parse_json(text_of(path), source), source, "",
                                 path.has_parent_path() ? path.parent_path() : fs::path("."));
}

TransferFunction parse_transfer_function(std::string_view text, const std::string& source, const Volume* volume,
                                         const fs::path& base_dir) {
  return TransferFunctionRequest(parse_json(text, source), source, "", base_dir).resolve(volume);
}

TransferFunction load_transfer_function(const fs::path& path, const Volume* volume) {
  return transfer_function_request(path).resolve(volume);
}

}  // namespace vri
