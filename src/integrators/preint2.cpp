#include "vri/integrators/preint2.hpp"

#include <algorithm>

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
  // The table is large (256 MiB at 256 entries a side): ask for the next
  // slab's four (s_f, s_m) rows of entries before compositing this one.
  const auto prefetch = [&](const std::array<double, 3>& s) {
    const ScalarAxis& axis = table_.axis();
    const auto lower = [&](double v) { return std::min(static_cast<int>(axis.index(v)), axis.n - 2); };
    const int f = lower(s[0]), m = lower(s[1]), b = lower(s[2]);
    for (int df = 0; df < 2; ++df)
      for (int dm = 0; dm < 2; ++dm) __builtin_prefetch(table_.entry(f + df, m + dm, b));
  };
  return detail::march_uniform_slabs<3>(
      volume_, tf_, ray, h_, [&](const std::array<double, 3>& s) { return table_.lookup(s[0], s[1], s[2]); },
      prefetch);
}

}  // namespace vri
