#pragma once
// MeshExactIntegrator (SPEC §9 `exact` on a tetrahedral mesh): the reference
// for mesh methods. The ray is walked cell to cell (TetWalk); inside each
// tetrahedron the scalar is linear along the ray, and the piece is integrated
// by the same PieceIntegrator as the grid `exact` (split at control points,
// closed-form optical depth, adaptive Gauss-Kronrod colour), with an absolute
// colour budget of tolerance spread over the ray's length in the mesh's box.
// The ray stops once the transmittance falls below tolerance/10 (divided by
// the brightest lit colour when lit).
// Lit (SPEC §5): the point gradients (PointGradients) are linear along the
// piece, so PieceIntegrator evaluates c_lit continuously and cuts the piece
// where N.d changes sign, as on grids.
#include <optional>

#include "vri/methods.hpp"  // the constructors' types
#include "piece_integrator.hpp"
#include "mesh/point_gradients.hpp"
#include "mesh/tet_walk.hpp"
#include "shading/headlight_shader.hpp"

namespace vri {

class MeshExactIntegrator final : public Integrator {
 public:
  // tolerance: absolute error bound per channel; throws unless 1e-12 <= tolerance <= 0.1.
  MeshExactIntegrator(const TetMesh& mesh, const TransferFunction& tf, double tolerance,
                      const Lighting& lighting = {});
  Rgba integrate(const Ray& ray) const override;
  std::string_view name() const override { return "exact"; }

 private:
  TetWalk walk_;
  PieceIntegrator pieces_;
  double tolerance_;
  std::optional<PointGradients> gradients_;
  std::optional<HeadlightShader> shader_;
};

// The registry's constructor (src/methods/method_registry.cpp): `exact` on
// tetrahedral meshes from a scene's method block.
std::unique_ptr<Integrator> make_mesh_exact(const MethodSpec& spec, const TetMesh& mesh, const TransferFunction& tf,
                                            const Lighting& lighting);

}  // namespace vri
