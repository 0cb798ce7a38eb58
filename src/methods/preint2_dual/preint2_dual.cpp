#include "preint2_dual.hpp"
#include "methods/preint/preint2.hpp"  // second_order_builder_name

#include <algorithm>
#include <cmath>

#include "dual_march.hpp"
#include "methods/march/float_packet.hpp"
#include "methods/preint/slab_policies.hpp"
#include "methods/march/ray_steps.hpp"
#include "vri/error.hpp"
#include "volume/cell_traversal.hpp"

namespace vri {

namespace {

// The shader of a lit scene, after checking the mode (before any table is built).
std::optional<HeadlightShader> dual_shader(const Lighting& lighting, const GridVolume& volume) {
  if (!lighting.enabled) return std::nullopt;
  if (lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error("preint2-dual: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  return std::optional<HeadlightShader>(std::in_place, lighting, volume);
}

// Walks the cell segments of `ray` and composites slab(front, middle, back)
// per segment, each a SlabSample<State> with state = at(p), and its length.
// Segments SegmentSkip leaves out are not sampled; the next segment sampled
// takes its front at the same position as without skipping, so the image is
// the same bytes. Stops once T < leap.termination.
template <class At, class Slab>
Rgba march_cells(const GridVolume& volume, const Ray& ray, const detail::Leap& leap, At&& at, Slab&& slab) {
  const auto whole = volume.clip(ray);
  if (!whole) return {0, 0, 0, 0};
  const Interval iv = owned_part(*whole);  // all of it unless a brick (GridVolume::Brick)
  const auto sample_at = [&](Vec3 p) { return detail::SlabSample<decltype(at(p))>{volume.sample(p), at(p)}; };
  detail::FrontToBack acc;
  detail::SegmentSkip skip(leap, ray, iv.t1);
  auto front = sample_at(ray.at(iv.t0));
  bool front_valid = true;  // false after a skipped segment: take it again at the next one's ta
  for_each_cell_segment(volume, ray, iv, [&](const CellSegment& seg) {
    if (acc.T < leap.termination) return false;
    if (skip.skipped(seg)) {
      front_valid = false;
      return true;
    }
    if (!front_valid) front = sample_at(ray.at(seg.ta)), front_valid = true;
    const auto middle = sample_at(ray.at(0.5 * (seg.ta + seg.tb))), back = sample_at(ray.at(seg.tb));
    const Rgba v = slab(front, middle, back, seg.tb - seg.ta);
    acc.add(v[0], v[1], v[2], v[3]);
    front = back;
    return true;
  });
  return acc.result();
}

}  // namespace

double Preint2DualIntegrator::max_slab_length(const GridVolume& volume) {
  const Vec3 sp = volume.spacing();
  return std::sqrt(3.0) * std::max({sp[0], sp[1], sp[2]});
}

Preint2DualIntegrator::Preint2DualIntegrator(const GridVolume& volume, const TransferFunction& tf, int table_size,
                                             int iterations, const std::string& builder, const Lighting& lighting,
                                             const FastPath& fast)
    : volume_(volume),
      shader_(dual_shader(lighting, volume)),
      tf_(tf, table_size, DataRange{volume.min_value(), volume.max_value()}),
      fast_(volume, ZeroOpacity(tf_, TableOrder::Second), fast, "preint2-dual"),
      float_sampler_(volume) {
  const DiscreteTf& d = tf_;
  const auto make = make_second_order_builder(builder);
  if (shader_ && lighting.mode == "interpolated")
    weighted_.emplace(build_second_order_weighted_length_tables(*make, d, kLengths, max_slab_length(volume), iterations));
  else
    table_.emplace(build_second_order_length_table(*make, d, kLengths, max_slab_length(volume), iterations));
  if (!fast.float_math) return;
  if (weighted_)
    float_table_ = std::make_unique<detail::DualFloatLookup>(weighted_->full, &weighted_->middle, &weighted_->back);
  else
    float_table_ = std::make_unique<detail::DualFloatLookup>(*table_);
  if (shader_) float_shading_ = std::make_unique<detail::FloatShading>(lighting, *shader_, float_sampler_);
  packets_ = detail::packets_fit(volume);  // (the float path: past the return above)
  // Cells inside non-empty macro cells whose corners' range (with the
  // rounding margin) lies where every second-order entry is zero: the
  // samples of their segments fall there, so the segments add nothing.
  if (const EmptySpace* space = fast_.space()) {
    const double margin = interpolation_margin(volume);
    const ZeroOpacityBins bins(*fast_.zero(), volume.min_value() - margin, volume.max_value() + margin);
    transparent_.emplace(volume, *space, bins, margin);
  }
}

detail::Leap Preint2DualIntegrator::leap() const {
  return {fast_.space(), fast_.termination(), fast_.zero(), transparent_ ? &*transparent_ : nullptr};
}

Preint2DualIntegrator::~Preint2DualIntegrator() = default;

const SecondOrderLengthTable& Preint2DualIntegrator::table() const { return weighted_ ? weighted_->full : *table_; }

Rgba Preint2DualIntegrator::integrate(const Ray& ray) const {
  const detail::Leap leap = this->leap();
  if (float_table_)
    return volume_.visit([&](auto values) {
      return detail::march_cells_float(volume_, values.data(), *float_table_, float_shading_.get(),
                                       weighted_.has_value(), ray, leap);
    });
  if (weighted_)
    return march_cells(
        volume_, ray, leap, [&](Vec3 p) { return shader_->at(p, ray.dir); },
        [&](const auto& f, const auto& m, const auto& b, double l) {
          const auto look = [&](const SecondOrderLengthTable& t) { return t.lookup(l, f.s, m.s, b.s); };
          return slabs::lit_lagrange(std::array{f.state, m.state, b.state}, look(weighted_->full), look(weighted_->middle),
                                     look(weighted_->back));
        });
  if (shader_)
    return march_cells(
        volume_, ray, leap, [&](Vec3 p) { return shader_->gradients().sample(p); },
        [&](const auto& f, const auto& m, const auto& b, double l) {
          return slabs::lit_by(shader_->terms(slabs::mean_gradient(std::array{f, m, b}), ray.dir),
                               table_->lookup(l, f.s, m.s, b.s));
        });
  struct Nothing {};
  return march_cells(
      volume_, ray, leap, [](Vec3) { return Nothing{}; },
      [&](const auto& f, const auto& m, const auto& b, double l) { return table_->lookup(l, f.s, m.s, b.s); });
}

void Preint2DualIntegrator::integrate_row(const Ray* rays, int n, Rgba* out) const {
  int i = 0;
  if (packets_) {
    const detail::Leap leap = this->leap();
    for (; i + detail::kPacket <= n; i += detail::kPacket)
      detail::march_dual_packet(volume_, *float_table_, float_shading_.get(), weighted_.has_value(), rays + i, leap,
                                out + i);
  }
  for (; i < n; ++i) out[i] = integrate(rays[i]);
}

std::unique_ptr<Integrator> make_preint2_dual(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                              const Lighting& lighting) {
  const int size = spec.table_size_given ? spec.table_size : Preint2DualIntegrator::kDefaultTableSize;
  return std::make_unique<Preint2DualIntegrator>(volume, tf, size, spec.iterations,
                                                 second_order_builder_name(spec.builder), lighting, spec.fast);
}

}  // namespace vri
