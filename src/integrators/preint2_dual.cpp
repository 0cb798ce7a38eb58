#include "vri/integrators/preint2_dual.hpp"

#include <algorithm>
#include <cmath>

#include "ray_steps.hpp"
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

}  // namespace

Preint2DualIntegrator::Preint2DualIntegrator(const GridVolume& volume, const TransferFunction& tf, int table_size,
                                             int iterations, const std::string& builder)
    : volume_(volume), table_(build_table(volume, tf, table_size, iterations, builder)) {}

Rgba Preint2DualIntegrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  detail::FrontToBack acc;
  double s_f = volume_.sample(ray.at(iv->t0));
  for_each_cell_segment(volume_, ray, *iv, [&](const CellSegment& seg) {
    const double s_m = volume_.sample(ray.at(0.5 * (seg.ta + seg.tb)));
    const double s_b = volume_.sample(ray.at(seg.tb));
    const Rgba v = table_.lookup(seg.tb - seg.ta, s_f, s_m, s_b);
    acc.add(v[0], v[1], v[2], v[3]);
    s_f = s_b;
    return true;
  });
  return acc.result();
}

}  // namespace vri
