// Empty-space skipping on the GPU, as the CPU's (fast_path.hpp,
// volume/empty_space.hpp): a macro cell (8 grid cells a side) that the CPU
// classified empty against the method's transfer function or table adds
// exactly nothing - a Riemann sample in it has tau = 0, a pre-integrated
// slab with all its samples in it reads all-zero entries - so a ray leaps
// from a sample in an empty macro cell to the last sample surely still in
// it, and the pixel keeps its bytes. The leap is computed from the ray's
// own parameterisation u = u0 + s du (s: the sample index plus the
// jitter's offset), kept short of the exit by 1e-3 + 1e-5 |s| samples so
// that float roundings of the exit never carry it past a sample outside.
// Needs before it: the macro cells' bits buffer `empty_cells`, and in `p`:
// skip (0: off), macro[3]; DF u0[3], du[3] (double_float.glsl); Cell
// (grid_sampler.glsl).

const int kMacroCells = 8;  // grid cells a side (MacroCells::kCells)

// Macro cell m (its index per axis) is empty and skipping is on.
bool macro_bit(ivec3 m) {
  if (p.skip == 0) return false;
  const uint i = uint(m.x + p.macro[0] * (m.y + p.macro[1] * m.z));
  return (empty_cells.bits[i >> 5] & (1u << (i & 31u))) != 0u;
}

bool macro_empty(Cell c) { return macro_bit(c.index / kMacroCells); }

// The parameter s just short of where the ray leaves the macro cell of `c`.
float macro_exit(Cell c) {
  const ivec3 m = c.index / kMacroCells;
  float s = 3.0e38;
  for (int a = 0; a < 3; ++a) {
    const float lo = float(m[a] * kMacroCells), hi = min(float((m[a] + 1) * kMacroCells), GRID_TOP(a));
    precise float from_lo = (lo - u0[a].hi) - u0[a].lo, from_hi = (hi - u0[a].hi) - u0[a].lo;
    if (du[a].hi > 0.0) s = min(s, from_hi / du[a].hi);
    else if (du[a].hi < 0.0) s = min(s, from_lo / du[a].hi);
  }
  return min(s - 1e-3 - 1e-5 * abs(s), 1.0e9);  // (an int after floor)
}
