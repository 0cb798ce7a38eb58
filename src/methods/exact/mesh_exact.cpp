#include "mesh_exact.hpp"

#include <algorithm>
#include <string>

#include "cubic.hpp"
#include "methods/march/early_stop.hpp"
#include "vri/error.hpp"

namespace vri {

MeshExactIntegrator::MeshExactIntegrator(const TetMesh& mesh, const TransferFunction& tf, double tolerance,
                                         const Lighting& lighting)
    : walk_(mesh), pieces_(tf), tolerance_(tolerance) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + format_g(tolerance));
  if (lighting.enabled) {
    gradients_.emplace(mesh);
    shader_.emplace(lighting, gradients_->flat_threshold());
  }
}

Rgba MeshExactIntegrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, walk_.mesh().box_lo(), walk_.mesh().box_hi());
  if (!iv) return {0, 0, 0, 0};
  PieceIntegrator::Accumulator acc;
  const double error_per_length = tolerance_ / iv->length();
  const double cutoff = early_stop_transmittance(tolerance_, brightest_colour(shader_));
  walk_.for_each_segment(ray, [&](const TetSegment& seg) {
    const double len = seg.tb - seg.ta;
    if (!shader_) {
      pieces_.integrate_linear(seg.s_front, seg.s_back, len, error_per_length, acc);
      return acc.T > cutoff;
    }
    const Vec3 g0 = gradients_->sample(seg.tet, ray.at(seg.ta)), g1 = gradients_->sample(seg.tet, ray.at(seg.tb));
    const Cubic grad[3] = {Cubic::linear(g0.x, g1.x, len), Cubic::linear(g0.y, g1.y, len),
                           Cubic::linear(g0.z, g1.z, len)};
    double kinks[3];
    const int nkinks = sign_changes(Cubic::linear(dot(g0, ray.dir), dot(g1, ray.dir), len), len, kinks);
    const PieceIntegrator::Lit lit{&*shader_, grad, ray.dir, kinks, nkinks};
    pieces_.integrate_linear(seg.s_front, seg.s_back, len, error_per_length, acc, &lit);
    return acc.T > cutoff;
  });
  return {acc.C[0], acc.C[1], acc.C[2], 1 - acc.T};
}

std::unique_ptr<Integrator> make_mesh_exact(const MethodSpec& spec, const TetMesh& mesh, const TransferFunction& tf,
                                            const Lighting& lighting) {
  return std::make_unique<MeshExactIntegrator>(mesh, tf, spec.tolerance, lighting);
}

}  // namespace vri
