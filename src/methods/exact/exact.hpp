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
// length) on each piece's integral before T(t_a) multiplies it (so the
// panels do not depend on T, and a brick of a distributed render takes the
// whole ray's), and the whole ray's colour error stays within `tolerance`.
// The ray stops once the transmittance falls below min(tolerance/10, 1e-7)
// (divided by the brightest lit colour when lighting is on), which bounds
// what is dropped.
// With lighting (SPEC §5), c is replaced by c_lit evaluated continuously; the
// pieces are also split where N.d changes sign (the kink of |N.d|): N.d is the
// interpolated gradient dotted with d, a cubic inside a cell.
#include <memory>
#include <optional>

#include "vri/methods.hpp"  // the constructors' types
#include "piece_integrator.hpp"
#include "shading/headlight_shader.hpp"
#include "vri/transfer_function.hpp"
#include "volume/cell_traversal.hpp"
#include "vri/volume.hpp"

namespace vri {

class ExactIntegrator final : public Integrator {
 public:
  // tolerance: absolute error bound per channel; throws unless 1e-12 <= tolerance <= 0.1.
  ExactIntegrator(const GridVolume& volume, const TransferFunction& tf, double tolerance,
                  const Lighting& lighting = {});
  ~ExactIntegrator() override;
  Rgba integrate(const Ray& ray) const override;
  const Footprint* footprint() const override { return &footprint_; }
  std::string_view name() const override { return "exact"; }

  using Accumulator = PieceIntegrator::Accumulator;
  // Integrates one cell piece of a ray with direction `dir` into `acc`;
  // error_per_length is the colour error allowed per unit of ray length.
  void integrate_cell(const CellSegment& seg, Vec3 dir, double error_per_length, Accumulator& acc) const;

 private:
  const GridVolume& volume_;
  const Footprint footprint_{volume_.whole_box(), {}};  // the volume's box
  double tolerance_;
  std::optional<HeadlightShader> shader_;
  PieceIntegrator pieces_;
};

// The registry's constructors (src/methods/method_registry.cpp): the integrator on grids from
// a scene's method block.
std::unique_ptr<Integrator> make_exact(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                       const Lighting& lighting);

}  // namespace vri
