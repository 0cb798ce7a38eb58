#include "verification/case_checks.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include "verification/reference_integral.hpp"
#include "vri/error.hpp"
#include "vri/render.hpp"

namespace vri::verify {

namespace {

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[160];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

class Runner {
 public:
  Runner(const Case& c, std::vector<Violation>& out) : case_(c), out_(out) {}

  // The image of `method`, or nullopt after recording a `finite` violation.
  std::optional<Image> render(const std::string& label, MethodSpec method, int threads = 1) {
    Scene scene = case_.scene;
    scene.method = std::move(method);
    try {
      return SceneRenderer(scene).render({.threads = threads});
    } catch (const std::exception& e) {
      out_.push_back({"finite", label, e.what()});
      return std::nullopt;
    }
  }

  void bounds(const std::string& label, const Image& image) {
    const bool lit = case_.scene.lighting.enabled;
    const auto d = image.data();
    for (std::size_t i = 0; i < d.size(); i += 4) {
      const float a = d[i + 3];
      if (!(a >= 0 && a <= 1 + 1e-6) || !(d[i] >= -1e-7 && d[i + 1] >= -1e-7 && d[i + 2] >= -1e-7)) {
        out_.push_back({"alpha-range", label, format("pixel %g: alpha %g", double(i / 4), a)});
        return;
      }
      for (int c = 0; c < 3 && !lit; ++c)
        if (!(d[i + c] <= a + 1e-5)) {
          out_.push_back({"colour-bound", label, format("pixel %g: colour over alpha by %g", double(i / 4), d[i + c] - a)});
          return;
        }
    }
  }

  void record(const char* check, const std::string& label, const std::string& detail) {
    out_.push_back({check, label, detail});
  }

 private:
  const Case& case_;
  std::vector<Violation>& out_;
};

double max_difference(const Image& a, const Image& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) m = std::max(m, std::abs(double(a.data()[i]) - b.data()[i]));
  return m;
}

double rms(const Image& a, const Image& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) s += std::pow(double(a.data()[i]) - b.data()[i], 2);
  return std::sqrt(s / a.data().size());
}

// How far the float path may stray from the double path here: 1e-4, plus
// what a scalar error of 1e-6 of the data range (float sample positions and
// interpolation) moves a sample's colour or its alpha over a step of `step`
// voxels on the steepest segment of the transfer function. nullopt where two
// control points (almost) coincide: a sample that close to a step may take
// either side of it in float, so no finite bound holds.
std::optional<double> float_double_bound(const Scene& scene, double step) {
  const auto& p = scene.transfer_function.points();
  const GridVolume& grid = scene.grid();
  const double range = std::max(double(grid.max_value()) - grid.min_value(), 1e-30);
  const double h = step * grid.voxel_unit();
  double steepest = 0;  // change per unit scalar
  for (std::size_t i = 1; i < p.size(); ++i) {
    const double ds = p[i].s - p[i - 1].s;
    if (!(ds > 1e-6 * range)) return std::nullopt;
    const double alpha = std::abs(std::exp(-p[i].tau * h) - std::exp(-p[i - 1].tau * h));
    for (double d : {std::abs(p[i].r - p[i - 1].r), std::abs(p[i].g - p[i - 1].g), std::abs(p[i].b - p[i - 1].b), alpha})
      steepest = std::max(steepest, d / ds);
  }
  return kFloatAgainstDouble + 1e-6 * range * steepest;
}

bool same_bytes(const Image& a, const Image& b) {
  return std::memcmp(a.data().data(), b.data().data(), a.data().size_bytes()) == 0;
}

}  // namespace

std::vector<Violation> check_case(const Case& c, const Checks& which) {
  std::vector<Violation> out;
  Runner run(c, out);
  const auto exact = run.render("exact", {.name = "exact", .tolerance = 1e-6});
  if (exact) run.bounds("exact", *exact);

  if (exact && !c.scene.lighting.enabled) {
    const double e = max_difference(*exact, reference_image(c.scene));
    if (!(e <= kExactAgainstReference))
      run.record("exact-vs-independent", "exact", format("max |exact - reference| %.3g (bound %.3g)", e, kExactAgainstReference));
  }

  auto rendered = [&](const std::string& label, const MethodSpec& m) {
    auto image = run.render(label, m);
    if (image) run.bounds(label, *image);
    return image;
  };
  // The float path against the double path of the same method and image.
  auto float_vs_double = [&](const std::string& label, const Image& image, MethodSpec m) {
    const std::optional<double> bound = float_double_bound(c.scene, m.step > 0 ? m.step : 1.0);
    if (!bound) return;
    m.fast.float_math = false;
    const auto twin = run.render(label + " double", m);
    if (!twin) return;
    const double e = max_difference(image, *twin);
    if (!(e <= *bound)) run.record("float-vs-double", label, format("max |float - double| %.3g (bound %.3g)", e, *bound));
  };
  if (const auto dual = rendered("preint2-dual", {.name = "preint2-dual"})) float_vs_double("preint2-dual", *dual, {.name = "preint2-dual"});
  rendered("adaptive coupled", {.name = "adaptive", .tolerance = 1e-3, .strategy = "coupled"});
  if (auto g = rendered("adaptive guaranteed", {.name = "adaptive", .tolerance = 1e-3, .strategy = "guaranteed"});
      g && exact) {
    const double e = max_difference(*g, *exact);
    if (!(e <= 1e-3 + 1e-6)) run.record("guaranteed", "adaptive guaranteed", format("max |guaranteed - exact| %.3g over 1e-3", e));
  }

  // Table methods at three steps: bounds, and no growth of the error as the
  // step halves. preint2's table has 64 entries a side (256^3 takes half a
  // second to build; the verification needs thousands). At step 0.5 the
  // same renderer's image with 2 threads (preint1), and without skipping,
  // must be the same bytes.
  auto table_method = [](const char* method, double step) {
    MethodSpec m{.name = method, .step = step};
    if (std::string(method) == "preint2") m.table_size = 64;
    return m;
  };
  for (const char* method : {"preint1", "preint2"}) {
    double previous = -1;
    for (double step : {1.0, 0.5, 0.25}) {
      const std::string label = std::string(method) + " step " + format("%g", step);
      Scene scene = c.scene;
      scene.method = table_method(method, step);
      std::optional<Image> image;
      try {
        const SceneRenderer renderer(scene);
        image = renderer.render({.threads = 1});
        if (step == 0.5 && std::string(method) == "preint1" && !same_bytes(*image, renderer.render({.threads = 2})))
          run.record("threads", method, "1 and 2 threads differ");
      } catch (const std::exception& e) {
        run.record("finite", label, e.what());
      }
      if (!image) break;
      run.bounds(label, *image);
      if (step == 0.5) {
        float_vs_double(label, *image, scene.method);
        scene.method.fast.skip_empty = false;
        if (const auto plain = run.render(label + " no skipping", scene.method); plain && !same_bytes(*image, *plain))
          run.record("skipping", method, "skipping changed the image");
      }
      if (!exact) continue;
      const double e = rms(*image, *exact);
      if (which.table_convergence && previous >= 0 && e > previous + 1e-4)
        run.record("table-convergence", method, format("RMS %.3g at half the step, was %.3g", e, previous));
      previous = e;
      // Second order against first order at the same step and table size.
      if (std::string(method) == "preint2" && which.second_order_wins) {
        MethodSpec first = table_method("preint1", step);
        first.table_size = scene.method.table_size;
        if (const auto one = run.render(label + " preint1 same table", first)) {
          const double e1 = rms(*one, *exact);
          if (e > e1 + 1e-4)
            run.record("preint2-vs-preint1", method, format("step %g: RMS %.3g, preint1's %.3g", step, e, e1));
        }
      }
    }
  }
  MethodSpec riemann{.name = "riemann", .step = 0.5};
  const auto skipped = run.render("riemann", riemann);
  riemann.fast.skip_empty = false;
  const auto plain = run.render("riemann no skipping", riemann);
  if (skipped) {
    run.bounds("riemann", *skipped);
    MethodSpec m{.name = "riemann", .step = 0.5};
    float_vs_double("riemann", *skipped, m);
  }
  if (skipped && plain && !same_bytes(*skipped, *plain)) run.record("skipping", "riemann", "skipping changed the image");
  return out;
}

}  // namespace vri::verify
