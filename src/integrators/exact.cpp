#include "vri/integrators/exact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cubic.hpp"
#include "vri/core/error.hpp"

namespace vri {

ExactIntegrator::ExactIntegrator(const GridVolume& volume, const TransferFunction& tf,
                                 double tolerance)
    : volume_(volume), pieces_(tf), tolerance_(tolerance) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + std::to_string(tolerance));
}

Rgba ExactIntegrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  Accumulator acc;
  const double error_per_length = tolerance_ / iv->length();
  const double cutoff = 0.1 * tolerance_;
  for_each_cell_segment(volume_, ray, *iv, [&](const CellSegment& seg) {
    integrate_cell(seg, error_per_length, acc);
    return acc.T > cutoff;
  });
  return {acc.C[0], acc.C[1], acc.C[2], 1 - acc.T};
}

void ExactIntegrator::integrate_cell(const CellSegment& cs, double error_per_length,
                                     Accumulator& acc) const {
  pieces_.integrate(trilinear_along(volume_, cs), cs.tb - cs.ta, error_per_length, acc);
}

}  // namespace vri
