#include "vri/tables/piece_weights.hpp"

#include <cmath>

#include "vri/tables/slab_integral.hpp"

namespace vri {

namespace {

// 6-point Gauss-Legendre on [0, 1]; symmetric: kX[5-g] = 1 - kX[g]. On a
// panel of optical depth <= 1 its relative error is below 1e-12.
constexpr int kG = 6;
constexpr double kX[kG] = {(1 - 0.9324695142031521) / 2, (1 - 0.6612093864662645) / 2,
                           (1 - 0.2386191860831969) / 2, (1 + 0.2386191860831969) / 2,
                           (1 + 0.6612093864662645) / 2, (1 + 0.9324695142031521) / 2};
constexpr double kW[kG] = {0.1713244923791704 / 2, 0.3607615730481386 / 2, 0.4679139345726910 / 2,
                           0.4679139345726910 / 2, 0.3607615730481386 / 2, 0.1713244923791704 / 2};

// int_0^1 exp(-x (a + k x)) dx for a thick piece: panels of optical depth <= 1,
// stopping where the depth reaches 50 (the rest is below e^-50).
double transmittance_integral(double a, double k) {
  const double x_max = reach_of_depth(a, k, 50);
  const int panels = panel_count(a, k, x_max, 1);
  const double w = x_max / panels;
  double sum = 0;
  for (int p = 0; p < panels; ++p)
    for (int g = 0; g < kG; ++g) {
      const double x = (p + kX[g]) * w;
      sum += kW[g] * std::exp(-x * (a + k * x));
    }
  return sum * w;
}

}  // namespace

PieceWeights thick_piece_weights(double A, double B) {
  const double em1 = std::expm1(-0.5 * (A + B));
  const double E = 1 + em1;
  const double k = 0.5 * (B - A);
  double Jf = 0, Jb = 0;
  if (std::max(A, B) <= 1) {
    // Backward depth at x is D(1) - D(1-x), and 1-x is a node too, so the
    // backward integrand there is E / (forward integrand at the mirror node).
    for (int g = 0; g < kG; ++g) {
      const double e = std::exp(-kX[g] * (A + k * kX[g]));
      Jf += kW[g] * e;
      Jb += kW[g] / e;
    }
    Jb *= E;
  } else {
    Jf = transmittance_integral(A, k);
    Jb = transmittance_integral(B, -k);
  }
  return {1 - Jf, Jf - E, 1 - Jb, Jb - E, -em1};
}

}  // namespace vri
