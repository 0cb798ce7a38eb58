#include "tables/piece_weights.hpp"

#include <cmath>

#include "tables/slab_integral.hpp"

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

// The optical depths at which transmittance_integral's panels end: half a
// depth each up to 4 (where tau rises from 0 the integrand is e^{-k x^2},
// whose first panel sets the error: 2e-13 against erf's closed form), then
// wider as what is left weighs less (a panel from depth d0 that adds w errs
// by about 2e-16 w^13 e^-d0 of the integral), to 50, past which the rest is
// below e^-50. 22 panels where uniform ones, one a depth by the largest rate,
// took up to 50 and more: tables of extinctions of 1e9 build several times
// faster (preint1 on a 12 x 12 view of such a case: 2.3 s to 0.24 s). Pieces
// at most 8 deep keep the uniform panels (the same bytes as before).
constexpr double kPanelDepths[] = {0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4, 5, 6, 7, 8, 10, 12, 14, 16, 20, 24, 28, 32, 40, 50};

// int_0^1 exp(-x (a + k x)) dx for a thick piece: one panel between each
// two of kPanelDepths (the depth is quadratic in x, so a panel's depth grows
// by exactly their difference), up to x = 1.
double transmittance_integral(double a, double k) {
  // Dense from the start, with the quadratic term small over the layer the
  // light comes from (|k| <= 3e-7 a^2): the integral over x >= 0 in closed
  // form, 1/a - 2k/a^3 + 12k^2/a^5, relatively within 1e-17 (the next term
  // is 120 (k/a^2)^3), past x = 1 lies less than e^-50.
  if (a > 50 && std::abs(k) <= 3e-7 * a * a) {
    const double r = k / (a * a);
    return (1 - 2 * r * (1 - 6 * r)) / a;
  }
  if (a + k <= 8) {  // the whole piece at most 8 deep: panels of one depth by the largest rate, as always
    const int panels = panel_count(a, k, 1, 1);
    const double w = 1.0 / panels;
    double sum = 0;
    for (int p = 0; p < panels; ++p)
      for (int g = 0; g < kG; ++g) {
        const double x = (p + kX[g]) * w;
        sum += kW[g] * std::exp(-x * (a + k * x));
      }
    return sum * w;
  }
  double sum = 0, x0 = 0;
  for (double depth : kPanelDepths) {
    const double x1 = reach_of_depth(a, k, depth), w = x1 - x0;
    for (int g = 0; g < kG; ++g) {
      const double x = x0 + kX[g] * w;
      sum += w * kW[g] * std::exp(-x * (a + k * x));
    }
    if (x1 >= 1) break;
    x0 = x1;
  }
  return sum;
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
