#pragma once
// Float elementary functions of the float paths (issue 8), written out so
// that the scalar marches and the 8-lane ray packets (float_packet.cpp:
// exp_neg8, log8) do the same operations in the same order and give the same
// bytes; the C library's expf and logf are not guaranteed to match any
// vector version. Both are Cephes' single-precision algorithms.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace vri::detail {

// exp(-x) for x >= 0 in float, to about one ulp: Cody and Waite's reduction
// x = n ln 2 + r (ln 2 split in two parts), the degree-6 polynomial of
// Cephes' expf on |r| <= ln 2 / 2, then 2^n from the exponent bits; below
// e^-87 (under float's normal range) it returns about 1.6e-38, which makes
// an opacity of 1. Also right for small negative x (a cosine a rounding
// above 1 in pow_unit).
namespace exp_poly {
inline constexpr float kMin = -87.0f, kLog2e = 1.44269504088896341f;
inline constexpr float kLn2Hi = 0.693359375f, kLn2Lo = -2.12194440e-4f;
inline constexpr float kP[6] = {1.9875691500e-4f, 1.3981999507e-3f, 8.3334519073e-3f,
                                4.1665795894e-2f, 1.6666665459e-1f, 5.0000001201e-1f};
}  // namespace exp_poly

inline float exp_neg(float x) {
  using namespace exp_poly;
  const float y = std::max(-x, kMin);
  const float n = std::floor(y * kLog2e + 0.5f);
  const float r = (y - n * kLn2Hi) - n * kLn2Lo;
  float p = kP[0];
  for (int i = 1; i < 6; ++i) p = p * r + kP[i];
  const float e = (p * (r * r) + r) + 1.0f;
  return e * std::bit_cast<float>(static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<int>(n) + 127) << 23));
}

// ln x for x >= FLT_MIN (normal floats), to about one ulp: x = m 2^e with
// m in [sqrt(1/2), sqrt(2)), ln(1 + (m - 1)) by Cephes' logf polynomial.
namespace log_poly {
inline constexpr float kSqrtHalf = 0.707106781186547524f, kMin = 1.17549435e-38f;
inline constexpr float kQ[9] = {7.0376836292e-2f, -1.1514610310e-1f, 1.1676998740e-1f,
                                -1.2420140846e-1f, 1.4249322787e-1f, -1.6668057665e-1f,
                                2.0000714765e-1f, -2.4999993993e-1f, 3.3333331174e-1f};
}  // namespace log_poly

inline float log_pos(float x) {
  using namespace log_poly;
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(std::max(x, kMin));
  float e = static_cast<float>(static_cast<int>(bits >> 23) - 126);
  float m = std::bit_cast<float>((bits & 0x807fffffu) | 0x3f000000u);  // in [1/2, 1)
  if (m < kSqrtHalf) {
    e = e - 1.0f;
    m = (m + m) - 1.0f;
  } else {
    m = m - 1.0f;
  }
  const float z = m * m;
  float y = kQ[0];
  for (int i = 1; i < 9; ++i) y = y * m + kQ[i];
  y = (y * m) * z;
  y = y + e * exp_poly::kLn2Lo;
  y = y - 0.5f * z;
  return (m + y) + e * exp_poly::kLn2Hi;
}

// x^p for x in [0, 1] (a cosine) and p >= 0: exp(p ln x), with 0^0 = 1.
inline float pow_unit(float x, float p) { return exp_neg(-(p * log_pos(x))); }

}  // namespace vri::detail
