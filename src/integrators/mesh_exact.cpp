#include "vri/integrators/mesh_exact.hpp"

#include <string>

#include "vri/core/error.hpp"

namespace vri {

MeshExactIntegrator::MeshExactIntegrator(const TetMesh& mesh, const TransferFunction& tf, double tolerance)
    : walk_(mesh), pieces_(tf), tolerance_(tolerance) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + std::to_string(tolerance));
}

Rgba MeshExactIntegrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, walk_.mesh().box_lo(), walk_.mesh().box_hi());
  if (!iv) return {0, 0, 0, 0};
  PieceIntegrator::Accumulator acc;
  const double error_per_length = tolerance_ / iv->length();
  const double cutoff = 0.1 * tolerance_;
  walk_.for_each_segment(ray, [&](const TetSegment& seg) {
    pieces_.integrate_linear(seg.s_front, seg.s_back, seg.tb - seg.ta, error_per_length, acc);
    return acc.T > cutoff;
  });
  return {acc.C[0], acc.C[1], acc.C[2], 1 - acc.T};
}

}  // namespace vri
