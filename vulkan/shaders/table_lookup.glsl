// preint1's table lookup in float, as FloatAxis and FloatLookup
// (include/vri/tables/float_lookup.hpp): a scalar's place on the table axis
// (entry i, weight w of entry i + 1), then the four entries around
// (s_f, s_b) blended bilinearly in the same order; `which` names the table
// of that layout to read (entry_of: the table itself, or a weighted table of
// interpolated lighting). Needs before it: vec4 entry_of(int which, int e)
// over tables of n x n entries (front scalar major) and, in `p`: table_n,
// table_lo, table_scale.

struct Place {
  int i;
  float w;
};

Place place(float s) {
  precise float u = clamp((s - p.table_lo) * p.table_scale, 0.0, float(p.table_n - 1));
  const int i = min(int(u), p.table_n - 2);
  precise float w = u - float(i);
  return Place(i, w);
}

vec4 blend(int which, Place f, Place b) {
  const int e = f.i * p.table_n + b.i;
  const vec4 e00 = entry_of(which, e), e01 = entry_of(which, e + 1), e10 = entry_of(which, e + p.table_n);
  const vec4 e11 = entry_of(which, e + p.table_n + 1);
  precise vec4 front = e00 + b.w * (e01 - e00);
  precise vec4 back = e10 + b.w * (e11 - e10);
  precise vec4 v = front + f.w * (back - front);
  return v;
}
