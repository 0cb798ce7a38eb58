#include "vri/integrators/preint1.hpp"

#include "preint1_slabs.hpp"
#include "vri/core/error.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri {

Preint1Integrator::Preint1Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, const std::string& builder, const Lighting& lighting)
    : volume_(volume),
      h_(detail::world_step(volume, step, "preint1")),
      tf_(tf, table_size),
      table_(make_table_builder(builder)->build(tf_, h_)) {
  if (!lighting.enabled) return;
  if (lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error("preint1: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  shader_.emplace(lighting, volume);
  if (lighting.mode == "interpolated") weighted_.emplace(build_weighted_tables(tf_, h_));
}

Rgba Preint1Integrator::integrate(const Ray& ray) const {
  using detail::march_uniform_slabs;
  if (weighted_) return march_uniform_slabs<2>(volume_, ray, h_, preint1::Interpolated{*weighted_, tf_, *shader_, ray.dir});
  if (shader_) return march_uniform_slabs<2>(volume_, ray, h_, preint1::Sampled{table_, tf_, *shader_, ray.dir});
  return march_uniform_slabs<2>(volume_, ray, h_, preint1::Unlit{table_, tf_});
}

}  // namespace vri
