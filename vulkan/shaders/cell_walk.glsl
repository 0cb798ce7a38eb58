// A ray's walk through the grid's cells, as the CPU's (cell_traversal.hpp;
// Amanatides & Woo 1987): the ray is cut where it crosses cell faces, each
// plane crossing recomputed from its integer index (no accumulated error),
// each piece's cell taken at its midpoint and clamped onto the grid. In
// double-float from the ray's entry (t in world units), so the pieces are
// the CPU's double ones up to roundings.
//   CellWalk w = walk_start();
//   while (df_less(w.ta, t_end)) { DF ta = w.ta, tb = walk_next(w, t_end); ...; w.ta = tb; }
// A piece may be empty (ta == tb where two faces are crossed at once).
// walk_leap passes over the rest of an empty macro cell.
// Needs before it: double_float.glsl, DF u0[3], du[3] (the grid position at
// the entry and per world unit), empty_space.glsl and in `p`: last_cell (GRID_TOP).

struct CellWalk {
  int dir[3];       // -1, 0, 1: the ray's direction per axis
  float plane[3];   // the next face crossed per axis
  DF t_next[3];     // where
  DF ta;            // the current piece's front
};

DF position(int a, DF t) { return df_add(u0[a], df_mul(du[a], t)); }

// Where the ray crosses plane `plane` of axis a.
DF crossing(int a, float plane) { return df_div(df_sub(DF(plane, 0.0), u0[a]), du[a]); }

CellWalk walk_start() {
  CellWalk w;
  const DF never = DF(3.0e38, 0.0);
  for (int a = 0; a < 3; ++a) {
    w.dir[a] = du[a].hi > 0.0 ? 1 : (du[a].hi < 0.0 ? -1 : 0);
    w.plane[a] = w.dir[a] > 0 ? df_floor(u0[a]) + 1.0 : -df_floor(df_neg(u0[a])) - 1.0;
    w.t_next[a] = w.dir[a] != 0 ? crossing(a, w.plane[a]) : never;
  }
  w.ta = DF(0.0, 0.0);
  return w;
}

// The back of the piece that starts at w.ta (the next face, or t_end); the
// faces at or before it are passed.
DF walk_next(inout CellWalk w, DF t_end) {
  const DF tb = df_min(df_min(w.t_next[0], w.t_next[1]), df_min(w.t_next[2], t_end));
  for (int a = 0; a < 3; ++a)
    while (w.dir[a] != 0 && !df_less(tb, w.t_next[a])) {
      w.plane[a] += float(w.dir[a]);
      w.t_next[a] = crossing(a, w.plane[a]);
    }
  return tb;
}

// The cell of the piece [ta, tb]: at its midpoint, clamped onto the grid.
ivec3 piece_cell(DF ta, DF tb) {
  const DF tm = df_mul(df_add(ta, tb), DF(0.5, 0.0));
  ivec3 index;
  for (int a = 0; a < 3; ++a) index[a] = int(clamp(df_floor(position(a, tm)), 0.0, float(p.last_cell[a])));
  return index;
}

// Grid position u(t) in the cell `index`'s coordinates (0 .. 1 inside it).
vec3 local_in(ivec3 index, DF t) {
  vec3 f;
  for (int a = 0; a < 3; ++a) f[a] = df_float(df_sub(position(a, t), DF(float(index[a]), 0.0)));
  return f;
}

// Passes over the rest of the macro cell of `cell` (empty: it adds nothing),
// the current piece's back at w.ta: the walk goes on from where the ray
// leaves the macro cell, with the faces it meets there. A crossing depends
// only on its plane's index, so the pieces after the leap are a full walk's.
void walk_leap(inout CellWalk w, ivec3 cell, DF t_end) {
  const ivec3 m = cell / kMacroCells;
  DF t_x = t_end;
  for (int a = 0; a < 3; ++a) {
    if (w.dir[a] == 0) continue;
    const float face = w.dir[a] > 0 ? min(float((m[a] + 1) * kMacroCells), GRID_TOP(a)) : float(m[a] * kMacroCells);
    t_x = df_min(t_x, crossing(a, face));
  }
  if (!df_less(w.ta, t_x)) return;
  w.ta = t_x;
  for (int a = 0; a < 3; ++a) {
    if (w.dir[a] == 0) continue;
    const DF u = position(a, t_x);
    w.plane[a] = w.dir[a] > 0 ? df_floor(u) + 1.0 : -df_floor(df_neg(u)) - 1.0;
    w.t_next[a] = crossing(a, w.plane[a]);
  }
}
