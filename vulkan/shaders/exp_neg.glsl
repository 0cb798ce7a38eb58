// exp(-x) for x >= 0, the CPU float paths' own (src/methods/march/float_math.hpp:
// Cephes' expf, Cody and Waite's reduction), operation for operation, so a GPU
// pixel differs from the CPU's by roundings alone and not by two different
// exp implementations.
float exp_neg(float x) {
  const float kMin = -87.0, kLog2e = 1.44269504088896341;
  const float kLn2Hi = 0.693359375, kLn2Lo = -2.12194440e-4;
  precise float y = max(-x, kMin);
  precise float n = floor(y * kLog2e + 0.5);
  precise float r = (y - n * kLn2Hi) - n * kLn2Lo;
  precise float p = 1.9875691500e-4;
  p = p * r + 1.3981999507e-3;
  p = p * r + 8.3334519073e-3;
  p = p * r + 4.1665795894e-2;
  p = p * r + 1.6666665459e-1;
  p = p * r + 5.0000001201e-1;
  precise float e = (p * (r * r) + r) + 1.0;
  return e * intBitsToFloat((int(n) + 127) << 23);
}

// 1 - exp(-x) for x >= 0 to float accuracy (the CPU's -expm1(-x) in double):
// below 1/2 its Taylor series to x^9 (the rest under 3e-9 of it), where
// 1 - exp_neg(x) would lose up to 6e-8 / x to cancellation; above, 1 - e^-x >= 0.39.
float one_minus_exp_neg(float x) {
  if (!(x < 0.5)) return 1.0 - exp_neg(x);
  precise float s = 1.0 / 362880.0;
  s = 1.0 / 40320.0 - x * s;
  s = 1.0 / 5040.0 - x * s;
  s = 1.0 / 720.0 - x * s;
  s = 1.0 / 120.0 - x * s;
  s = 1.0 / 24.0 - x * s;
  s = 1.0 / 6.0 - x * s;
  s = 0.5 - x * s;
  s = 1.0 - x * s;
  return x * s;
}
