// The pre-integration tables' lookups in float, as FloatAxis, FloatLookup
// and SecondOrderFloatLookup (src/tables/float_lookup.hpp,
// second_order_float_lookup.hpp): a scalar's place on the table axis (entry
// i, weight w of entry i + 1), then the entries around it blended in the
// same order: preint1's four around (s_f, s_b) bilinearly, preint2's eight
// around (s_f, s_m, s_b) trilinearly, along s_b, then s_m, then s_f. `which`
// names the table of that layout to read (entry_of: the table itself, or a
// weighted table of interpolated lighting). Needs before it:
// vec4 entry_of(int which, uint e) over tables of n^2 or n^3 entries (front
// scalar major) and, in `p`: table_n, table_lo, table_scale.

struct Place {
  int i;
  float w;
};

// Where slab length l falls among `lengths` slices of lengths
// max_length m / (lengths - 1) (length_bracket, slab_table.hpp): slice i and
// the weight w of slice i + 1, l clamped to [0, max_length].
Place length_place(float l, float max_length, int lengths) {
  precise float u = clamp(l / max_length, 0.0, 1.0) * float(lengths - 1);
  const int i = min(int(u), lengths - 2);
  precise float w = u - float(i);
  return Place(i, w);
}

// Two slices' values blended by the length's weight.
vec4 between(vec4 lo, vec4 hi, Place l) {
  precise vec4 v = lo + l.w * (hi - lo);
  return v;
}

Place place(float s) {
  precise float u = clamp((s - p.table_lo) * p.table_scale, 0.0, float(p.table_n - 1));
  const int i = min(int(u), p.table_n - 2);
  precise float w = u - float(i);
  return Place(i, w);
}

// Entries e and e + 1 blended by w (along the back scalar).
vec4 along(int which, uint e, float w) {
  const vec4 lo = entry_of(which, e), hi = entry_of(which, e + 1u);
  precise vec4 v = lo + w * (hi - lo);
  return v;
}

// The first-order table whose first entry is entry `base` of `which`
// (tet-raycast's tables of several lengths, one after another).
vec4 blend_at(int which, uint base, Place f, Place b) {
  const uint n = uint(p.table_n), e = base + uint(f.i) * n + uint(b.i);
  const vec4 front = along(which, e, b.w), back = along(which, e + n, b.w);
  precise vec4 v = front + f.w * (back - front);
  return v;
}

// The second-order table `which` (preint2's; preint2-dual reads its tables
// of several lengths in its own order, preint2_dual.comp).
vec4 blend(int which, Place f, Place m, Place b) {
  const uint n = uint(p.table_n), row = n, plane = n * n;
  const uint e = uint(f.i) * plane + uint(m.i) * row + uint(b.i);
  const vec4 c00 = along(which, e, b.w), c01 = along(which, e + row, b.w);
  const vec4 c10 = along(which, e + plane, b.w), c11 = along(which, e + plane + row, b.w);
  precise vec4 c0 = c00 + m.w * (c01 - c00);
  precise vec4 c1 = c10 + m.w * (c11 - c10);
  precise vec4 v = c0 + f.w * (c1 - c0);
  return v;
}

vec4 blend(int which, Place f, Place b) { return blend_at(which, 0u, f, b); }
