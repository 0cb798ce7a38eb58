#include "vri/integrators/preint1.hpp"

#include <cmath>

#include "vri/core/error.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri {

namespace {

double world_step(const GridVolume& volume, double step) {
  if (!(step >= 1e-4 && step <= 1e4))
    throw Error("preint1: step must be in [1e-4, 1e4] voxel units, got " + std::to_string(step));
  return step * volume.voxel_unit();
}

}  // namespace

Preint1Integrator::Preint1Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, const std::string& builder)
    : volume_(volume),
      h_(world_step(volume, step)),
      tf_(tf, table_size),
      table_(make_table_builder(builder)->build(tf_, h_)) {}

Rgba Preint1Integrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const long long full = static_cast<long long>(std::floor(iv->length() / h_));
  double T = 1, C[3] = {0, 0, 0};
  const auto composite = [&](double r, double g, double b, double a) {
    C[0] += T * r;
    C[1] += T * g;
    C[2] += T * b;
    T *= 1 - a;
  };
  double s_front = volume_.sample(ray.at(iv->t0));
  for (long long k = 1; k <= full; ++k) {
    const double s_back = volume_.sample(ray.at(iv->t0 + k * h_));
    const Rgba v = table_.lookup(s_front, s_back);
    composite(v[0], v[1], v[2], v[3]);
    s_front = s_back;
  }
  const double rest = iv->t1 - (iv->t0 + full * h_);
  if (rest > 0) {
    const SlabRgba v = exact_slab(tf_, s_front, volume_.sample(ray.at(iv->t1)), rest);
    composite(v.r, v.g, v.b, v.a);
  }
  return {C[0], C[1], C[2], 1 - T};
}

}  // namespace vri
