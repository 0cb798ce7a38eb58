#pragma once
// GuaranteedAdaptiveIntegrator (SPEC §9 `adaptive`, strategy `guaranteed`):
// vri's extension of Campagnolo, Celes & de Figueiredo 2015 that aims to meet
// the tolerance on every pixel, where the paper leaves up to 0.12% of pixels
// above it (its Tables I, II, VI).
//
// The paper's estimate E = |D - S|/15 (its Sec. III) is only trustworthy on a
// smooth integrand, and hmin stops refinement where it is not. Here:
//  - the ray is cut where it crosses cell faces (the trilinear signal has a
//    kink there) and where the signal crosses a transfer-function control
//    point (kink or step of the transfer function), so every Simpson step
//    lies on one smooth piece; transparent pieces take no samples;
//  - inner (optical depth) and outer (r, g, b, alpha) integrals are tried on
//    the same five samples, and a step is accepted only when both meet their
//    share of the budget, with the paper's step control (Algorithm 2) inside
//    each piece, starting from the whole piece, at most hmax, with no hmin
//    (a floor of 1e-4 voxel units only guarantees termination; a piece too
//    dense for any step over it goes to `exact`'s PieceIntegrator);
//  - the tolerance is shared along the ray and between the integrals: with L
//    the ray's length in the volume, a step of length h may err by
//    0.45 tol h / L in colour and by 0.45 tol h / (L T) in optical depth (an
//    optical-depth error d changes everything behind it, at most T, by d);
//    the ray stops when T < 0.1 tol, which drops at most 0.1 tol.
// Lit (SPEC §5): samples carry c_lit, with the gradient as the cell's three
// cubics along the ray; pieces are also cut where N.d changes sign (kink of
// |N.d|), the optical-depth share and the stop are divided by the
// brightest lit colour, ka + kd + ks (when above 1), and steps are at most a
// quarter voxel (the specular spike near a vanishing gradient is narrow).
// Samples come from the cell's cubic and the piece's linear transfer-function
// segment, so an evaluation costs a few multiplications. Unlit, a cell whose
// field lies in one segment (its cubic's Bernstein hull) is one piece, and the
// cells' cubics and the pieces' first tries are made four at a time, lanes
// over cells or pieces (src/methods/adaptive/cell_cubics.hpp, guaranteed_tries.hpp),
// with the bytes of one at a time.
// Empty space (issue 21): the ray walks only the runs of macro cells that the
// transfer function does not map to zero extinction everywhere
// (volume/empty_space.hpp, the macro cells of the uniform marchers) and
// leaps over the rest, whose pieces are transparent and take no samples
// anyway: the image is the same up to the rounding of a run's first face. In
// the runs, a cell whose corners' range has no extinction is skipped before
// its cubic is built; those cells are found once per transfer function
// (volume/transparent_cells.hpp), so the walk skips them on one bit.
#include <memory>
#include <optional>

#include "adaptive_params.hpp"
#include "vri/methods.hpp"
#include "methods/fast_path.hpp"
#include "methods/exact/piece_integrator.hpp"
#include "shading/headlight_shader.hpp"
#include "vri/transfer_function.hpp"
#include "vri/volume.hpp"
#include "volume/transparent_cells.hpp"

namespace vri {

class TfPieceSplitter;

class GuaranteedAdaptiveIntegrator final : public ErrorEstimatingIntegrator {
 public:
  // Throws vri::Error for bad parameters (params.strategy is not consulted).
  GuaranteedAdaptiveIntegrator(const GridVolume& volume, const TransferFunction& tf,
                               const AdaptiveParams& params, const Lighting& lighting = {});
  ~GuaranteedAdaptiveIntegrator() override;
  using ErrorEstimatingIntegrator::integrate;
  Rgba integrate(const Ray& ray, RayStats& stats) const override;
  const Footprint* footprint() const override { return &skipping_.footprint(); }
  std::string_view name() const override { return "adaptive"; }

 private:
  template <class Value>  // on the volume's typed samples (GridVolume::visit)
  Rgba integrate_typed(const Value* values, const Ray& ray, RayStats& stats) const;

  const GridVolume& volume_;
  double tolerance_;
  double hmax_, hfloor_;  // world units
  std::unique_ptr<const TfPieceSplitter> splitter_;
  std::optional<HeadlightShader> shader_;
  ZeroOpacity zero_;           // where tf has no extinction
  double margin_;              // EmptySpace's margin: rounding of interpolated scalars
  ZeroOpacityBins zero_bins_;  // zero_ in O(1) over the volume's range, for the cell test
  Skipping skipping_;  // the empty macro cells, against tf
  // The cells of the non-empty macro cells that zero_bins_ finds
  // transparent, classified once (with skipping on).
  std::optional<TransparentCells> transparent_;
  // Pieces too dense for any step over the floor (step_cap below it:
  // extinctions of 1e8 and more) are integrated as `exact` integrates them,
  // to the same error density (issue 46: the floor overrode the cap, 30 % of
  // pixels over at 1e8, errors up to 0.9).
  PieceIntegrator dense_;
};

}  // namespace vri
