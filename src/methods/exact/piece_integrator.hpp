#pragma once
// PieceIntegrator: the exact integral of SPEC §4 along one piece of a ray on
// which the scalar is a polynomial s(t) of degree <= 3 (a grid cell: cubic;
// a tetrahedron: linear). Shared by the grid and mesh `exact` integrators and
// by the brute-force (l, s_f, s_b) table. The piece is split where s crosses a
// transfer-function control point (TfPieceSplitter); on each sub-piece
// tau(s(t)) is a cubic, its integral (the optical depth) a quartic taken in
// closed form, and the colour integral is adaptive Gauss-Kronrod (7/15) to an
// absolute budget of error_per_length per unit of ray length.
#include <memory>

#include "vri/geometry.hpp"
#include "shading/headlight_shader.hpp"
#include "vri/transfer_function.hpp"

namespace vri {

struct Cubic;            // src/methods/exact/cubic.hpp
class TfPieceSplitter;   // src/methods/exact/tf_pieces.hpp

class PieceIntegrator {
 public:
  // Front-to-back state: transmittance so far and premultiplied colour.
  struct Accumulator {
    double T = 1;
    double C[3] = {0, 0, 0};
    long panels = 0;  // Gauss-Kronrod panels spent on this ray so far
  };
  // Lighting along the piece (SPEC §5): c_lit = c a + b with the shader's terms
  // for the gradient grad(t) (three cubics); the terms have kinks where N.d
  // changes sign, at `kinks` (ascending), where the colour integral is cut too.
  struct Lit {
    const HeadlightShader* shader;
    const Cubic* grad;
    Vec3 dir;
    const double* kinks;
    int nkinks;
  };

  // The cap on work per ray: integrate() throws vri::Error (naming the cap and
  // kMaxPanelsVariable) once one accumulator has spent more panels. A panel is
  // 15 evaluations; the default is far beyond any real ray (a 512^3 diagonal
  // crosses ~1500 cells and a few panels each), so only pathological input hits it.
  static constexpr long kDefaultMaxPanels = 1000000;
  static constexpr const char* kMaxPanelsVariable = "VRI_EXACT_MAX_PANELS";
  // kDefaultMaxPanels, or the value of the environment variable kMaxPanelsVariable.
  static long default_max_panels();

  // Keeps a reference to tf.
  explicit PieceIntegrator(const TransferFunction& tf, long max_panels = default_max_panels());
  ~PieceIntegrator();

  // Integrates s(t), t in [0, len], into acc; unlit when lit is null.
  void integrate(const Cubic& s, double len, double error_per_length, Accumulator& acc,
                 const Lit* lit = nullptr) const;
  // The linear case: s goes from s_front to s_back over length len.
  void integrate_linear(double s_front, double s_back, double len, double error_per_length,
                        Accumulator& acc, const Lit* lit = nullptr) const;

 private:
  std::unique_ptr<const TfPieceSplitter> splitter_;
  long max_panels_;
};

}  // namespace vri
