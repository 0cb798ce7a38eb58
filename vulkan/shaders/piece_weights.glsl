// PieceWeights (src/tables/piece_weights.hpp, piece_weights.cpp) in
// float: how one piece of a slab - tau and c linear in t, optical
// thicknesses A and B at its ends - turns colours into premultiplied colour,
// forward and backward (integration by parts, docs/PREINTEGRATION.md §2):
//   fp = 1 - J(A,B), fq = J(A,B) - E, bq = 1 - J(B,A), bp = J(B,A) - E, alpha = 1 - E,
// J(A,B) = int_0^1 exp(-A x - (B-A) x^2 / 2) dx, E = exp(-(A+B)/2). Thin
// pieces (A, B <= 1/8) by the CPU's series, thicker ones by 6-point
// Gauss-Legendre on panels of optical depth <= 1. Needs exp_neg.glsl and
// one_minus_exp_neg.

struct PieceWeights {
  float fp, fq, bq, bp, alpha;
};

// sum_i c[j][i] s^i for j = 1 .. 6 (piece_series::kC), Horner.
float series_c(int j, float s) {
  if (j == 1) return ((((-1.4880952e-4 * s + 9.9206349e-4) * s - 5.5555556e-3) * s + 0.025) * s - 0.083333333) * s + 0.16666667;
  if (j == 2) return (((8.2671958e-5 * s - 4.9603175e-4) * s + 2.3809524e-3) * s - 8.3333333e-3) * s + 0.016666667;
  if (j == 3) return ((-3.3068783e-5 * s + 1.6534392e-4) * s - 5.9523810e-4) * s + 1.1904762e-3;
  if (j == 4) return (9.0187590e-6 * s - 3.3068783e-5) * s + 6.6137566e-5;
  if (j == 5) return -1.5031265e-6 * s + 3.0062530e-6;
  return 1.1562512e-7;
}

PieceWeights thin_piece_weights(float A, float B) {
  const float kJ0m1[9] = float[9](-0.5, 0.16666667, -0.041666667, 8.3333333e-3, -1.3888889e-3, 1.9841270e-4,
                                  -2.4801587e-5, 2.7557319e-6, -2.7557319e-7);
  const float kJ0me[9] = float[9](0.5, -0.33333333, 0.125, -0.033333333, 6.9444444e-3, -1.1904762e-3,
                                  1.7361111e-4, -2.2045855e-5, 2.4801587e-6);
  const float sigma = 0.5 * (A + B), delta = 0.5 * (B - A), d2 = delta * delta;
  float j0m1 = 0.0, j0me = 0.0;
  for (int i = 8; i >= 0; --i) {
    j0m1 = (j0m1 + kJ0m1[i]) * sigma;
    j0me = (j0me + kJ0me[i]) * sigma;
  }
  const float even = d2 * (series_c(2, sigma) + d2 * (series_c(4, sigma) + d2 * series_c(6, sigma)));
  const float odd = delta * (series_c(1, sigma) + d2 * (series_c(3, sigma) + d2 * series_c(5, sigma)));
  return PieceWeights(-(j0m1 + even) - odd, j0me + even + odd, -(j0m1 + even) + odd, j0me + even - odd,
                      j0me - j0m1);
}

// 6-point Gauss-Legendre on [0, 1].
const float kGaussX[6] = float[6](0.033765243, 0.16939531, 0.38069041, 0.61930959, 0.83060469, 0.96623476);
const float kGaussW[6] = float[6](0.085662246, 0.18038079, 0.23395697, 0.23395697, 0.18038079, 0.085662246);

// int_0^1 exp(-x (a + k x)) dx on panels of optical depth <= 1, up to depth 50
// (slab_integral.cpp: reach_of_depth, panel_count).
float transmittance_integral(float a, float k) {
  const float x_max = a + k <= 50.0 ? 1.0 : 100.0 / (a + sqrt(a * a + 200.0 * k));
  const int panels = int(clamp(ceil(max(a, a + 2.0 * k * x_max) * x_max), 1.0, 65536.0));
  const float w = x_max / float(panels);
  float sum = 0.0;
  for (int q = 0; q < panels; ++q)
    for (int g = 0; g < 6; ++g) {
      const float x = (float(q) + kGaussX[g]) * w;
      sum += kGaussW[g] * exp_neg(x * (a + k * x));
    }
  return sum * w;
}

PieceWeights piece_weights(float A, float B) {
  if (max(A, B) <= 0.125) return thin_piece_weights(A, B);
  const float alpha = one_minus_exp_neg(0.5 * (A + B)), E = 1.0 - alpha;
  const float k = 0.5 * (B - A);
  float jf = 0.0, jb = 0.0;
  if (max(A, B) <= 1.0) {
    for (int g = 0; g < 6; ++g) {
      const float e = exp_neg(kGaussX[g] * (A + k * kGaussX[g]));
      jf += kGaussW[g] * e;
      jb += kGaussW[g] / e;
    }
    jb *= E;
  } else {
    jf = transmittance_integral(A, k);
    jb = transmittance_integral(B, -k);
  }
  return PieceWeights(1.0 - jf, jf - E, 1.0 - jb, jb - E, alpha);
}

// One piece of length d from p to q (r, g, b, tau), forward (p at the front)
// and backward (slab_integral.hpp, linear_piece).
void linear_piece(vec4 p, vec4 q, float d, out vec4 forward, out vec4 backward) {
  const PieceWeights w = piece_weights(p.w * d, q.w * d);
  forward = vec4(p.rgb * w.fp + q.rgb * w.fq, w.alpha);
  backward = vec4(q.rgb * w.bq + p.rgb * w.bp, w.alpha);
}

// front seen in front of back (slab_rgba.hpp).
vec4 over(vec4 front, vec4 back) { return front + (1.0 - front.a) * back; }
