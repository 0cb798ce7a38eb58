#pragma once
// ExactIntegrator (SPEC §9 `exact`): the reference every other method is
// judged by. The ray is split where it crosses cell faces (inside a cell the
// trilinear signal s(t) is a cubic) and again where s(t) crosses a transfer-
// function control point (kinks and steps). On each resulting piece tau is
// linear in s, so tau(t) is a cubic polynomial and the optical depth is a
// quartic integrated in closed form; the colour integral
//   C = sum_pieces T(t_a) * int c(s(t)) tau(t) exp(-int_{t_a}^t tau) dt
// has a smooth (entire) integrand and is computed by adaptive Gauss-Kronrod
// (7/15) with an absolute error budget of tolerance * (piece length / ray
// length), so the whole ray's colour error stays within `tolerance`.
// The ray stops once the transmittance falls below tolerance/10 (divided by
// the brightest lit colour when lighting is on), which bounds what is dropped.
// With lighting (SPEC §5), c is replaced by c_lit evaluated continuously; the
// pieces are also split where N.d changes sign (the kink of |N.d|): N.d is the
// interpolated gradient dotted with d, a cubic inside a cell.
#include <optional>

#include "vri/integrators/integrator.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/cell_traversal.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

class ExactIntegrator final : public Integrator {
 public:
  // tolerance: absolute error bound per channel; throws unless 1e-12 <= tolerance <= 0.1.
  ExactIntegrator(const GridVolume& volume, const TransferFunction& tf, double tolerance,
                  const Lighting& lighting = {});
  Rgba integrate(const Ray& ray) const override;
  std::string_view name() const override { return "exact"; }

  struct Accumulator {
    double T = 1;
    double C[3] = {0, 0, 0};
  };
  // Integrates one cell piece of a ray with direction `dir` into `acc`;
  // error_per_length is the colour error allowed per unit of ray length.
  void integrate_cell(const CellSegment& seg, Vec3 dir, double error_per_length, Accumulator& acc) const;

 private:
  const GridVolume& volume_;
  const TransferFunction& tf_;
  double tolerance_;
  std::optional<HeadlightShader> shader_;
  std::vector<int> opaque_prefix_;  // opaque_prefix_[i]: non-transparent segments before i
};

}  // namespace vri
