#include "vri/integrators/preint1.hpp"

#include "ray_steps.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri {

Preint1Integrator::Preint1Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, const std::string& builder)
    : volume_(volume),
      h_(detail::world_step(volume, step, "preint1")),
      tf_(tf, table_size),
      table_(make_table_builder(builder)->build(tf_, h_)) {}

Rgba Preint1Integrator::integrate(const Ray& ray) const {
  return detail::march_uniform_slabs<2>(volume_, tf_, ray, h_,
                                        [&](const std::array<double, 2>& s) { return table_.lookup(s[0], s[1]); });
}

}  // namespace vri
