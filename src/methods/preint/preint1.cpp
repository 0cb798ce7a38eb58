#include "preint1.hpp"

#include "float_march.hpp"
#include "methods/march/float_packet.hpp"
#include "methods/march/float_shading.hpp"
#include "slab_policies.hpp"
#include "vri/error.hpp"
#include "tables/slab_integral.hpp"
#include "tables/table_builder.hpp"

namespace vri {

Preint1Integrator::Preint1Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, const std::string& builder, const Lighting& lighting,
                                     const FastPath& fast)
    : volume_(volume),
      h_(detail::world_step(volume, step, "preint1")),
      tf_(tf, table_size, DataRange{volume.min_value(), volume.max_value()}),
      table_(make_table_builder(builder)->build(tf_, h_)),
      fast_(volume, ZeroOpacity(tf_), fast, "preint1"),
      float_math_(fast.float_math),
      float_sampler_(volume),
      float_table_(table_),
      packets_(float_math_ && detail::packets_fit(volume)) {
  if (!lighting.enabled) return;
  if (lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error("preint1: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  shader_.emplace(lighting, volume);
  if (lighting.mode == "interpolated") weighted_.emplace(build_weighted_tables(tf_, h_));
  if (float_math_) float_shading_ = std::make_unique<detail::FloatShading>(lighting, *shader_, float_sampler_);
}

Preint1Integrator::~Preint1Integrator() = default;

namespace {

// The float march's lighting: none, sampled, or interpolated with the
// weighted tables (front, back), which share the unweighted table's layout.
detail::FloatLighting float_lighting(const detail::FloatShading* shading, const std::optional<WeightedTables>& w) {
  detail::FloatLighting out{shading, {}};
  if (w) out.weighted = {w->front.data().data(), w->back.data().data(), nullptr};
  return out;
}

}  // namespace

Rgba Preint1Integrator::integrate(const Ray& ray) const {
  using detail::march_uniform_slabs;
  using Table = PreintegrationTable;
  const detail::Leap leap{fast_.space(), fast_.termination(), fast_.zero()};
  const detail::NoPrefetch none;
  if (float_math_)
    return volume_.visit([&](auto values) {
      return detail::march_float(volume_, float_sampler_, values.data(), float_table_, tf_,
                                 float_lighting(float_shading_.get(), weighted_), ray, h_, leap);
    });
  if (weighted_)
    return march_uniform_slabs<2>(volume_, ray, h_, slabs::Interpolated1{{tf_, *shader_, ray.dir}, *weighted_}, none,
                                  leap);
  if (shader_)
    return march_uniform_slabs<2>(volume_, ray, h_, slabs::Sampled<2, Table>{table_, tf_, *shader_, ray.dir}, none,
                                  leap);
  return march_uniform_slabs<2>(volume_, ray, h_, slabs::Unlit<2, Table>{table_, tf_}, none, leap);
}

void Preint1Integrator::integrate_row(const Ray* rays, int n, Rgba* out) const {
  int i = 0;
  if (packets_) {
    const detail::Leap leap{fast_.space(), fast_.termination(), fast_.zero()};
    for (; i + detail::kPacket <= n; i += detail::kPacket)
      detail::march_preint1_packet(volume_, float_sampler_, float_table_, tf_,
                                   float_lighting(float_shading_.get(), weighted_), rays + i, h_, leap, out + i);
  }
  for (; i < n; ++i) out[i] = integrate(rays[i]);
}

std::unique_ptr<Integrator> make_preint1(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                         const Lighting& lighting) {
  return std::make_unique<Preint1Integrator>(volume, tf, spec.step, spec.table_size, spec.builder, lighting, spec.fast);
}

}  // namespace vri
