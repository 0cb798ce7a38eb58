#include "preint2.hpp"

#include <algorithm>

#include "float_march.hpp"
#include "methods/march/float_packet.hpp"
#include "methods/march/float_shading.hpp"
#include "slab_policies.hpp"
#include "vri/error.hpp"

namespace vri {

std::string second_order_builder_name(const std::string& builder) {
  return builder == "plain" || builder == "fast" ? builder : "fast";
}

namespace {

// The table is large (256 MiB at 256 entries a side): ask for the next
// slab's four (s_f, s_m) rows of entries before compositing this one.
template <class Sample>
void prefetch_rows(const SecondOrderTable& table, const std::array<Sample, 3>& s) {
  const ScalarAxis& axis = table.axis();
  const auto lower = [&](double v) { return std::min(static_cast<int>(axis.index(v)), axis.n - 2); };
  const int f = lower(s[0].s), m = lower(s[1].s), b = lower(s[2].s);
  for (int df = 0; df < 2; ++df)
    for (int dm = 0; dm < 2; ++dm) __builtin_prefetch(table.entry(f + df, m + dm, b));
}

}  // namespace

Preint2Integrator::Preint2Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, int iterations, const std::string& builder,
                                     const Lighting& lighting, const FastPath& fast)
    : volume_(volume),
      h_(detail::world_step(volume, step, "preint2")),
      tf_(tf, table_size, DataRange{volume.min_value(), volume.max_value()}),
      fast_(volume, ZeroOpacity(tf_, TableOrder::Second), fast, "preint2"),
      float_sampler_(volume),
      packets_(fast.float_math && detail::packets_fit(volume)) {
  const auto make = make_second_order_builder(builder);
  if (lighting.enabled) {
    if (lighting.mode != "sampled" && lighting.mode != "interpolated")
      throw Error("preint2: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
    shader_.emplace(lighting, volume);
  }
  if (lighting.enabled && lighting.mode == "interpolated")
    weighted_.emplace(make->build_weighted(tf_, 2 * h_, iterations));
  else
    table_.emplace(make->build(tf_, 2 * h_, iterations));
  if (!fast.float_math) return;
  float_table_.emplace(table());
  if (shader_) float_shading_ = std::make_unique<detail::FloatShading>(lighting, *shader_, float_sampler_);
}

Preint2Integrator::~Preint2Integrator() = default;

namespace {

// The float march's lighting: none, sampled, or interpolated with the three
// weighted tables (full, middle, back; the lookup reads full's layout).
detail::FloatLighting float_lighting(const detail::FloatShading* shading,
                                     const std::optional<SecondOrderWeightedTables>& w) {
  detail::FloatLighting out{shading, {}};
  if (w) out.weighted = {w->full.data(), w->middle.data(), w->back.data()};
  return out;
}

}  // namespace

const SecondOrderTable& Preint2Integrator::table() const { return weighted_ ? weighted_->full : *table_; }

Rgba Preint2Integrator::integrate(const Ray& ray) const {
  using detail::march_uniform_slabs;
  const detail::Leap leap{fast_.space(), fast_.termination(), fast_.zero()};
  if (float_table_)
    return volume_.visit([&](auto values) {
      return detail::march_float(volume_, float_sampler_, values.data(), *float_table_, tf_,
                                 float_lighting(float_shading_.get(), weighted_), ray, h_, leap);
    });
  if (weighted_) {
    const auto prefetch = [&](const auto& s) {
      for (const SecondOrderTable* t : {&weighted_->full, &weighted_->middle, &weighted_->back}) prefetch_rows(*t, s);
    };
    return march_uniform_slabs<3>(volume_, ray, h_, slabs::Interpolated2{{tf_, *shader_, ray.dir}, *weighted_},
                                  prefetch, leap);
  }
  const auto prefetch = [&](const auto& s) { prefetch_rows(*table_, s); };
  using Table = SecondOrderTable;
  if (shader_)
    return march_uniform_slabs<3>(volume_, ray, h_, slabs::Sampled<3, Table>{*table_, tf_, *shader_, ray.dir},
                                  prefetch, leap);
  return march_uniform_slabs<3>(volume_, ray, h_, slabs::Unlit<3, Table>{*table_, tf_}, prefetch, leap);
}

void Preint2Integrator::integrate_row(const Ray* rays, int n, Rgba* out) const {
  int i = 0;
  if (packets_) {
    const detail::Leap leap{fast_.space(), fast_.termination(), fast_.zero()};
    for (; i + detail::kPacket <= n; i += detail::kPacket)
      detail::march_preint2_packet(volume_, float_sampler_, *float_table_, tf_,
                                   float_lighting(float_shading_.get(), weighted_), rays + i, h_, leap, out + i);
  }
  for (; i < n; ++i) out[i] = integrate(rays[i]);
}

std::unique_ptr<Integrator> make_preint2(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                         const Lighting& lighting) {
  return std::make_unique<Preint2Integrator>(volume, tf, spec.step, spec.table_size, spec.iterations,
                                             second_order_builder_name(spec.builder), lighting, spec.fast);
}

}  // namespace vri
