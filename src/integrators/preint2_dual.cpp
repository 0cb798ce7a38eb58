#include "vri/integrators/preint2_dual.hpp"

#include <algorithm>
#include <cmath>

#include "preint2_slabs.hpp"
#include "ray_steps.hpp"
#include "vri/core/error.hpp"
#include "vri/volume/cell_traversal.hpp"

namespace vri {

namespace {

double longest_chord(const GridVolume& volume) {
  const Vec3 sp = volume.spacing();
  return std::sqrt(3.0) * std::max({sp[0], sp[1], sp[2]});
}

SecondOrderLengthTable build_table(const GridVolume& volume, const TransferFunction& tf, int table_size,
                                   int iterations, const std::string& builder) {
  const DiscreteTf discrete(tf, table_size);
  return build_second_order_length_table(*make_second_order_builder(builder), discrete,
                                         Preint2DualIntegrator::kLengths, longest_chord(volume), iterations);
}

// The shader of a lit scene, after checking the mode (before any table is built).
std::optional<HeadlightShader> dual_shader(const Lighting& lighting, const GridVolume& volume) {
  if (!lighting.enabled) return std::nullopt;
  if (lighting.mode == "interpolated")
    throw Error("preint2-dual: lighting mode interpolated is not supported (it needs 3 weighted tables over "
                "(l, s_f, s_m, s_b), docs/LIGHTING.md); use sampled, or preint2");
  if (lighting.mode != "sampled")
    throw Error("preint2-dual: lighting mode must be sampled, got '" + lighting.mode + "'");
  return std::optional<HeadlightShader>(std::in_place, lighting, volume);
}

// Walks the cell segments of `ray` and composites light(state_f, state_m,
// state_b, lookup) per segment, state = at(p) at each sample.
template <class At, class Light>
Rgba march_cells(const GridVolume& volume, const SecondOrderLengthTable& table, const Ray& ray, At&& at,
                 Light&& light) {
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) return {0, 0, 0, 0};
  detail::FrontToBack acc;
  Vec3 p = ray.at(iv->t0);
  double s_f = volume.sample(p);
  auto front = at(p);
  for_each_cell_segment(volume, ray, *iv, [&](const CellSegment& seg) {
    const Vec3 p_m = ray.at(0.5 * (seg.ta + seg.tb)), p_b = ray.at(seg.tb);
    const double s_m = volume.sample(p_m), s_b = volume.sample(p_b);
    const auto back = at(p_b);
    const Rgba v = light(front, at(p_m), back, table.lookup(seg.tb - seg.ta, s_f, s_m, s_b));
    acc.add(v[0], v[1], v[2], v[3]);
    s_f = s_b;
    front = back;
    return true;
  });
  return acc.result();
}

}  // namespace

Preint2DualIntegrator::Preint2DualIntegrator(const GridVolume& volume, const TransferFunction& tf, int table_size,
                                             int iterations, const std::string& builder, const Lighting& lighting)
    : volume_(volume),
      shader_(dual_shader(lighting, volume)),
      table_(build_table(volume, tf, table_size, iterations, builder)) {}

Rgba Preint2DualIntegrator::integrate(const Ray& ray) const {
  if (shader_)
    return march_cells(
        volume_, table_, ray, [&](Vec3 p) { return shader_->gradients().sample(p); },
        [&](Vec3 f, Vec3 m, Vec3 b, const Rgba& v) {
          return preint1::lit_by(shader_->terms(preint2::mean_gradient(f, m, b), ray.dir), v);
        });
  struct Nothing {};
  return march_cells(
      volume_, table_, ray, [](Vec3) { return Nothing{}; }, [](Nothing, Nothing, Nothing, const Rgba& v) { return v; });
}

}  // namespace vri
