#pragma once
// Four doubles in one GCC vector, for the adaptive integrators' Simpson
// tries (methods/adaptive/simpson_colour_step.cpp): r, g, b and alpha of a sample,
// or the four new samples of a step. Written with GCC's vector extensions,
// not intrinsics, so that the same code compiles to SSE2 pairs on x86-64's
// baseline and to one AVX2 register in an "avx2" clone (simd.hpp,
// VRI_AVX2_CLONES) with the same bytes: neither target fuses a * b + c.
#include <cstdint>
#include <cstring>

namespace vri::f64x4 {

typedef double V __attribute__((vector_size(32)));
typedef std::int64_t I __attribute__((vector_size(32)));

inline V splat(double x) { return V{x, x, x, x}; }
inline V load(const double* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store(double* p, V v) { std::memcpy(p, &v, sizeof v); }
inline V abs(V x) { return x < 0 ? -x : x; }
inline double max_lane(V x) {
  const double a = x[0] > x[1] ? x[0] : x[1], b = x[2] > x[3] ? x[2] : x[3];
  return a > b ? a : b;
}

// exp(-x) lane by lane for finite x, to about one ulp: Cephes' exp (Moshier),
// x = n ln 2 + r with |r| <= ln 2 / 2 (ln 2 in two parts), the Pade form
// e^r = 1 + 2 r P(r^2) / (Q(r^2) - r P(r^2)), then 2^n from the exponent
// bits. n is rounded by adding and subtracting 1.5 * 2^52 (no vector floor on
// the baseline target). -x is clamped to [-708, 708], so below e^-708 it
// returns about 3e-308 where the C library would return less or 0: no sum of
// transmittances vri forms can tell them apart.
inline V exp_neg(V x) {
  constexpr double kLog2e = 1.4426950408889634073599, kC1 = 6.93145751953125e-1, kC2 = 1.42860682030941723212e-6;
  constexpr double kRound = 6755399441055744.0;  // 1.5 * 2^52
  V y = -x;
  y = y < -708.0 ? splat(-708.0) : y;
  y = y > 708.0 ? splat(708.0) : y;
  const V shifted = y * kLog2e + kRound;  // n = y log2 e rounded to nearest, in the low bits
  const V n = shifted - kRound;
  const V r = (y - n * kC1) - n * kC2;
  const V rr = r * r;
  const V p = r * ((1.26177193074810590878e-4 * rr + 3.02994407707441961300e-2) * rr + 9.99999999999999999910e-1);
  const V q = ((3.00198505138664455042e-6 * rr + 2.52448340349684104192e-3) * rr + 2.27265548208155028766e-1) * rr +
              2.00000000000000000009e0;
  const V e = 1.0 + 2.0 * (p / (q - p));
  // 2^n: n sits in the low bits of `shifted` (biased by kRound's bits).
  I bits, round_bits;
  std::memcpy(&bits, &shifted, sizeof bits);
  const V k = splat(kRound);
  std::memcpy(&round_bits, &k, sizeof round_bits);
  const I pow2 = ((bits - round_bits) + 1023) << 52;
  V scale;
  std::memcpy(&scale, &pow2, sizeof scale);
  return e * scale;
}

}  // namespace vri::f64x4
