// Positions along a ray in double-float (a value as hi + lo, two floats;
// Dekker 1971, Knuth's two-sum): the CPU float paths place sample k at
// u0 + k du in double (float_march.hpp, float_riemann.hpp); in float alone a
// position 500 voxels in would be off by 3e-5 voxel, and a steep transfer
// function turns that into visible differences. Not every GPU has float64
// (Apple's none, consumer NVIDIA's at 1/64 rate): these need only fma-free
// float arithmetic, kept exact by `precise` (no contraction, no reordering).

struct DF {
  float hi, lo;
};

DF df_two_sum(float a, float b) {
  precise float s = a + b;
  precise float bb = s - a;
  precise float e = (a - (s - bb)) + (b - bb);
  return DF(s, e);
}

DF df_fast_two_sum(float a, float b) {  // |a| >= |b|
  precise float s = a + b;
  precise float e = b - (s - a);
  return DF(s, e);
}

// a * b exactly as hi + lo, by Dekker's split (no fma: the same on every device).
DF df_two_prod(float a, float b) {
  precise float p = a * b;
  precise float ca = 4097.0 * a;
  precise float ah = ca - (ca - a);
  precise float al = a - ah;
  precise float cb = 4097.0 * b;
  precise float bh = cb - (cb - b);
  precise float bl = b - bh;
  precise float e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
  return DF(p, e);
}

DF df_add(DF a, DF b) {
  DF s = df_two_sum(a.hi, b.hi);
  precise float lo = s.lo + (a.lo + b.lo);
  return df_fast_two_sum(s.hi, lo);
}

DF df_mul(DF a, DF b) {
  DF p = df_two_prod(a.hi, b.hi);
  precise float lo = p.lo + (a.hi * b.lo + a.lo * b.hi);
  return df_fast_two_sum(p.hi, lo);
}

DF df_neg(DF a) { return DF(-a.hi, -a.lo); }
DF df_sub(DF a, DF b) { return df_add(a, df_neg(b)); }
bool df_less(DF a, DF b) { return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo); }
DF df_min(DF a, DF b) { return df_less(b, a) ? b : a; }
float df_floor(DF a) {
  float f = floor(a.hi);
  if (f == a.hi && a.lo < 0.0) f -= 1.0;
  return f;
}
float df_float(DF a) { return a.hi + a.lo; }
// a / b to about 44 bits (one correction step).
DF df_div(DF a, DF b) {
  precise float q1 = a.hi / b.hi;
  const DF r = df_sub(a, df_mul(DF(q1, 0.0), b));
  precise float q2 = r.hi / b.hi;
  return df_two_sum(q1, q2);
}
// sqrt(a) to about 44 bits (one Newton step on the float root); 0 for a <= 0.
DF df_sqrt(DF a) {
  if (!(a.hi > 0.0)) return DF(0.0, 0.0);
  precise float q = sqrt(a.hi);
  const DF r = df_sub(a, df_two_prod(q, q));
  precise float c = r.hi / (2.0 * q);
  return df_fast_two_sum(q, c);
}
// An int exactly (its top 23 bits and its low 8, each exact in float).
DF df_from_int(int n) { return df_two_sum(float(n >> 8) * 256.0, float(n & 255)); }
// floor(a) as an int, clamped to [-2^31 + 128, 2^31 - 128] (the largest floats an int holds).
int df_floor_int(DF a) { return int(clamp(df_floor(a), -2147483520.0, 2147483520.0)); }
