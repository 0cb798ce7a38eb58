#pragma once
// PieceIntegrator: the exact integral of SPEC §4 along one piece of a ray on
// which the scalar is a polynomial s(t) of degree <= 3 (a grid cell: cubic;
// a tetrahedron: linear). Shared by the grid and mesh `exact` integrators and
// by the brute-force (l, s_f, s_b) table. The piece is split where s crosses a
// transfer-function control point; on each sub-piece tau(s(t)) is a cubic,
// its integral (the optical depth) a quartic taken in closed form, and the
// colour integral is adaptive Gauss-Kronrod (7/15) to an absolute budget of
// error_per_length per unit of ray length.
#include <vector>

#include "vri/transfer/transfer_function.hpp"

namespace vri {

struct Cubic;  // src/integrators/cubic.hpp

class PieceIntegrator {
 public:
  // Front-to-back state: transmittance so far and premultiplied colour.
  struct Accumulator {
    double T = 1;
    double C[3] = {0, 0, 0};
  };

  // Keeps a reference to tf.
  explicit PieceIntegrator(const TransferFunction& tf);

  // Integrates s(t), t in [0, len], into acc.
  void integrate(const Cubic& s, double len, double error_per_length, Accumulator& acc) const;
  // The linear case: s goes from s_front to s_back over length len.
  void integrate_linear(double s_front, double s_back, double len, double error_per_length,
                        Accumulator& acc) const;

 private:
  const TransferFunction& tf_;
  std::vector<int> opaque_prefix_;  // opaque_prefix_[i]: non-transparent segments before i
};

}  // namespace vri
