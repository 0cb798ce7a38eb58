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
// The ray stops once the transmittance falls below tolerance/10, which bounds
// what is dropped (alpha and colour) by tolerance/10.
#include <memory>

#include "vri/integrators/integrator.hpp"
#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/cell_traversal.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

class TfPieceSplitter;

class ExactIntegrator final : public Integrator {
 public:
  // tolerance: absolute error bound per channel; throws unless 1e-12 <= tolerance <= 0.1.
  ExactIntegrator(const GridVolume& volume, const TransferFunction& tf, double tolerance);
  ~ExactIntegrator() override;
  Rgba integrate(const Ray& ray) const override;
  std::string_view name() const override { return "exact"; }

  struct Accumulator {
    double T = 1;
    double C[3] = {0, 0, 0};
  };
  // Integrates one cell piece into `acc`; error_per_length is the colour error
  // allowed per unit of ray length. Public for tests of single cells.
  void integrate_cell(const CellSegment& seg, double error_per_length, Accumulator& acc) const;

 private:
  const GridVolume& volume_;
  double tolerance_;
  std::unique_ptr<const TfPieceSplitter> splitter_;
};

}  // namespace vri
