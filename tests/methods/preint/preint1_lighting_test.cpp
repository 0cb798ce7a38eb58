// Lit preint1 (SPEC §5, lighting.mode sampled / interpolated) against lit exact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "test_support.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

Image render_with(const Scene& s, const MethodSpec& spec, const Lighting& lighting) {
  return render(Camera(s.camera), *make_integrator(spec, s.grid(), s.transfer_function, lighting));
}

// RMS over the colour channels of a - b (- (c - d) when given).
double rms_rgb(const Image& a, const Image& b, const Image* c = nullptr, const Image* d = nullptr) {
  double sum = 0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) {
    if (i % 4 == 3) continue;
    const double e = a.data()[i] - b.data()[i] - (c ? c->data()[i] - d->data()[i] : 0.0);
    sum += e * e, ++n;
  }
  return std::sqrt(sum / n);
}

Lighting with_mode(Lighting l, const char* mode) {
  l.mode = mode;
  return l;
}

Scene small(const char* name, int side) {
  Scene s = load_scene(test::source_path(std::string("scenes/") + name));
  s.camera.width = s.camera.height = side;
  return s;
}

// Constant shading terms take the tables apart: a = 1, b = 0 must give the
// unlit image (D_front + D_back = C_1), a = 0, b = 1 (ks = 1, p = 0) the
// opacity in every colour channel (S_front + S_back = alpha). The field has
// no flat spot, where SPEC §5 would drop the specular term.
TEST(Preint1Lighting, ConstantTermsGiveUnlitColourAndOpacity) {
  const GridVolume volume = test::volume_from({24, 24, 24}, [](double x, double y, double z) {
    return 3.5 * (x + y + z) + 10 * std::sin(0.3 * x) * std::cos(0.2 * y);
  });
  const TransferFunction tf = small("neghip_lit.json", 1).transfer_function;
  const Camera camera({.eye = {70, 55, 80}, .target = {11.5, 11.5, 11.5}, .up = {0, 0, 1}, .width = 24, .height = 24});
  const MethodSpec pre{.name = "preint1", .step = 1.3};  // leaves partial last slabs
  const auto image = [&](const Lighting& l) { return render(camera, *make_integrator(pre, volume, tf, l)); };
  const Image unlit = image({});
  for (const char* mode : {"sampled", "interpolated"}) {
    const Image colour = image({true, 1, 0, 0, 32, mode}), white = image({true, 0, 0, 1, 0, mode});
    double worst_colour = 0, worst_white = 0;
    for (std::size_t i = 0; i < unlit.data().size(); ++i) {
      worst_colour = std::max(worst_colour, double(std::abs(colour.data()[i] - unlit.data()[i])));
      worst_white = std::max(worst_white, double(std::abs(white.data()[i] - unlit.data()[i - i % 4 + 3])));
    }
    EXPECT_LT(worst_colour, 1e-5) << mode;
    EXPECT_LT(worst_white, 1e-5) << mode;
  }
  EXPECT_GT(*std::max_element(unlit.data().begin(), unlit.data().end()), 0.3f);  // not an empty image
}

// Four transparent isosurfaces (narrow spikes) of neghip, 32 x 32: both modes
// converge to lit exact, about first order in the step (measured orders
// 1.1 - 1.3 for both).
TEST(Preint1Lighting, BothModesConvergeToLitExact) {
  const Scene s = small("neghip_lit.json", 32);
  const Image ref = render_with(s, {.name = "exact", .tolerance = 1e-7}, s.lighting);
  for (const char* mode : {"sampled", "interpolated"}) {
    std::vector<double> err;
    // From step 1/2: neghip_lit's spikes reach tau 15, so a step of one voxel
    // is not yet in the asymptotic range (order 0.4 from 1 to 1/2).
    for (double step : {0.5, 0.25, 0.125, 0.0625})
      err.push_back(rms_rgb(render_with(s, {.name = "preint1", .step = step}, with_mode(s.lighting, mode)), ref));
    for (std::size_t i = 1; i < err.size(); ++i) {
      const double order = std::log2(err[i - 1] / err[i]);
      std::printf("lit preint1 %s step %g: rms %.3e, order %.2f\n", mode, 0.5 / (1 << i), err[i], order);
      EXPECT_GT(order, 0.7) << mode << " " << i;
    }
    EXPECT_LT(err.back(), 1.5e-3) << mode;
  }
}

// The same slabs lit two ways, fuel with four narrow spikes, 64 x 64 at step
// 2. The shading error - the lit-minus-unlit image against exact's
// lit-minus-unlit, which removes the unlit slab error both modes share - is
// smaller with interpolated lighting; the total error is not, because the
// unlit error (the scalar's and the table's interpolation) dominates it and
// the sampled normal happens to offset it more (docs/LIGHTING.md).
TEST(Preint1Lighting, InterpolatedShadesCloserToExactThanSampled) {
  const Scene s = small("fuel_lit.json", 64);
  const Lighting off{};
  const MethodSpec exact{.name = "exact", .tolerance = 1e-7}, pre{.name = "preint1", .step = 2.0};
  const Image ref = render_with(s, exact, s.lighting), ref_unlit = render_with(s, exact, off);
  const Image unlit = render_with(s, pre, off);
  const Image sampled = render_with(s, pre, with_mode(s.lighting, "sampled"));
  const Image interpolated = render_with(s, pre, with_mode(s.lighting, "interpolated"));
  const double shading_ratio = rms_rgb(interpolated, unlit, &ref, &ref_unlit) / rms_rgb(sampled, unlit, &ref, &ref_unlit);
  const double total_ratio = rms_rgb(interpolated, ref) / rms_rgb(sampled, ref);
  std::printf("interpolated / sampled: shading error %.3f, total error %.3f\n", shading_ratio, total_ratio);
  EXPECT_LT(shading_ratio, 0.9);  // measured 0.848 (0.79 before issue 20's brighter spikes)
  EXPECT_GT(total_ratio, 1.0);    // measured 1.026 (1.27 before)
  EXPECT_LT(total_ratio, 1.4);
}

}  // namespace
}  // namespace vri
