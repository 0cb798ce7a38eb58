#include "vri/render.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "vri/error.hpp"
#include "vri/methods.hpp"

namespace vri {

TerminationBound termination_bound(const Image& image, double termination) {
  TerminationBound bound;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const double remaining = 1 - double(image.pixel(x, y)[3]);
      if (!(remaining < termination)) continue;
      ++bound.pixels;
      bound.max_remaining = std::max(bound.max_remaining, remaining);
    }
  return bound;
}

namespace {

std::string g(double v) { return format_g(v); }

// The step a method takes along a ray, in voxel units; 1 for methods that
// step cell by cell (exact, preint2-dual) or that are not stepped at all.
double step_of(const MethodSpec& m, const char** key) {
  const std::string_view parameter = known_method(m.name).step_parameter;
  *key = parameter == "step" ? "step" : parameter == "hmin" ? "hmin" : nullptr;
  return parameter == "step" ? m.step : parameter == "hmin" ? m.hmin : 1.0;
}

struct Bounds {
  Vec3 lo, hi;
  double voxel_unit;
  double s_min, s_max;
};

Bounds bounds_of(const Scene& scene) {
  return std::visit(
      [](const auto& v) {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, GridVolume>)  // a part of a grid: the whole grid's box
          return Bounds{v.whole_lo(), v.whole_hi(), v.voxel_unit(), double(v.min_value()), double(v.max_value())};
        else
          return Bounds{v.box_lo(), v.box_hi(), v.mean_edge_length(), double(v.min_value()), double(v.max_value())};
      },
      scene.volume);
}

}  // namespace

int checked_threads(int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw Error("--threads: expected an integer in [0, " + std::to_string(kMaxThreads) + "] (0: all cores), found " +
                std::to_string(threads));
  return threads;
}

void check_work(const Scene& scene, const Camera& camera) {
  const MethodSpec& m = scene.method;
  const Bounds b = bounds_of(scene);
  const char* key = nullptr;
  const double h = step_of(m, &key) * b.voxel_unit;
  const double diagonal = length(b.hi - b.lo);
  const double per_ray = std::ceil(diagonal / h) + 1;
  const double pixels = double(camera.width()) * camera.height();
  const std::string by = key ? std::string(" with method.") + key + " " + g(step_of(m, &key)) : std::string();
  if (per_ray > m.max_samples)
    throw Error("'" + m.name + "'" + by + " takes about " + g(per_ray) + " samples per ray (volume diagonal " +
                g(diagonal) + ", voxel unit " + g(b.voxel_unit) + "), over the cap of " + g(m.max_samples) +
                "; raise it with --max-samples N (scene method.max_samples) or use a larger step");
  if (per_ray * pixels > m.max_work)
    throw Error("'" + m.name + "'" + by + " takes about " + g(per_ray * pixels) + " samples in all (" + g(per_ray) +
                " per ray x " + g(pixels) + " pixels), over the cap of " + g(m.max_work) +
                "; raise it with --max-work N (scene method.max_work), or use a larger step or a smaller image");
}

namespace {

// Whether every value is finite: a value is not where its exponent bits are
// all ones, and adding one to that field then carries into the top bit.
// Integer and/add/or only, so that the compiler vectorizes it: the check
// runs on every frame, in one thread, after the parallel render (a find_if
// with std::isfinite took about 1 ms of a 30 ms 512^2 frame).
bool all_finite(std::span<const float> d) {
  constexpr std::uint32_t kExponent = 0x7f800000u, kOne = 0x00800000u;
  std::uint32_t carried = 0;
  for (const float v : d) carried |= (std::bit_cast<std::uint32_t>(v) & kExponent) + kOne;
  return !(carried & 0x80000000u);
}

}  // namespace

void refuse_non_finite(const Image& image, const std::string& what) {
  const auto& d = image.data();
  if (all_finite(d)) return;
  const auto bad = std::find_if(d.begin(), d.end(), [](float v) { return !std::isfinite(v); });
  if (bad == d.end()) return;
  const std::size_t i = std::size_t(bad - d.begin()), pixel = i / 4;
  const auto count = std::count_if(d.begin(), d.end(), [](float v) { return !std::isfinite(v); });
  static const char* channel[] = {"r", "g", "b", "a"};
  throw Error(what + " holds " + std::to_string(count) + " non-finite values (first " + g(*bad) + " at pixel (" +
              std::to_string(pixel % std::size_t(image.width())) + ", " +
              std::to_string(pixel / std::size_t(image.width())) + ") channel " + channel[i % 4] +
              "); nothing was written");
}

std::optional<std::string> transparency_cause(const Image& image, const Scene& scene, const Camera& camera) {
  const auto& d = image.data();
  for (std::size_t i = 3; i < d.size(); i += 4)
    if (d[i] != 0) return std::nullopt;
  const Bounds b = bounds_of(scene);
  // The transfer function is piecewise linear: its largest extinction over
  // the data range lies at an end or at a breakpoint inside.
  const TransferFunction& tf = scene.transfer_function;
  double tau = std::max(tf(b.s_min).tau, tf(b.s_max).tau);
  for (const ControlPoint& p : tf.points())
    if (p.s >= b.s_min && p.s <= b.s_max) tau = std::max(tau, p.tau);
  bool hits = false;
  for (int y = 0; y < camera.height() && !hits; ++y)
    for (int x = 0; x < camera.width() && !hits; ++x) hits = clip_to_box(camera.ray(x, y), b.lo, b.hi).has_value();
  std::string cause;
  if (!hits)
    cause = "the camera looks away from the volume (no ray meets its box " + g(b.lo.x) + "," + g(b.lo.y) + "," +
            g(b.lo.z) + " .. " + g(b.hi.x) + "," + g(b.hi.y) + "," + g(b.hi.z) + ")";
  else if (tau == 0)
    cause = "the transfer function is transparent over the data range [" + g(b.s_min) + ", " + g(b.s_max) +
            "] (its control points span [" + g(tf.s_lo()) + ", " + g(tf.s_hi()) + "])";
  else
    cause = "the rays cross only data the transfer function makes transparent";
  return cause;
}

}  // namespace vri
