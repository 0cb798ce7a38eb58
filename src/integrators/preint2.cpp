#include "vri/integrators/preint2.hpp"

#include "ray_steps.hpp"

namespace vri {

std::string second_order_builder_name(const std::string& builder) {
  return builder == "plain" || builder == "fast" ? builder : "fast";
}

Preint2Integrator::Preint2Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, int iterations, const std::string& builder)
    : volume_(volume),
      h_(detail::world_step(volume, step, "preint2")),
      tf_(tf, table_size),
      table_(make_second_order_builder(builder)->build(tf_, 2 * h_, iterations)) {}

Rgba Preint2Integrator::integrate(const Ray& ray) const {
  return detail::march_uniform_slabs<3>(
      volume_, tf_, ray, h_, [&](const std::array<double, 3>& s) { return table_.lookup(s[0], s[1], s[2]); });
}

}  // namespace vri
