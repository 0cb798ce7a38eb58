// The runs of empty and non-empty macro cells along a ray, as the CPU's
// EmptySpace::Walk (volume/empty_space.hpp; for_each_occupied_run visits the
// non-empty ones): one walk of the macro cells from the one at the ray's
// entry (a 3D DDA over their faces, Amanatides & Woo 1987), a run ending
// where the ray enters a cell of the other kind, the next starting there.
// The first macro cell is the one of the grid cell that trilinear
// interpolation at the entry reads (clamped onto the grid). In double-float
// from the ray's entry, so a run's ends are the CPU's up to roundings; an
// integrator whose steps start at a run's entry (adaptive.comp) then places
// them where the CPU does. With skipping off the one run is the whole ray.
// Needs before it: empty_space.glsl, cell_walk.glsl (position, crossing).

struct MacroRun {
  bool empty;
  DF t_end;
};

struct MacroWalk {
  ivec3 m, step;  // the current macro cell; the ray's direction per axis
  DF leave[3];    // where the ray leaves it per axis
  bool done;
};

// Where the ray leaves the walk's macro cell through its face on axis a
// (empty_space.glsl's macro_exit is the marchers' sample parameter short of it).
DF walk_exit(MacroWalk w, int a) {
  if (w.step[a] == 0) return DF(3.0e38, 0.0);
  return crossing(a, float((w.m[a] + (w.step[a] > 0 ? 1 : 0)) * kMacroCells));
}

MacroWalk macro_walk_start() {
  MacroWalk w;
  for (int a = 0; a < 3; ++a) {
    w.m[a] = int(clamp(df_floor(u0[a]), 0.0, float(p.last_cell[a]))) / kMacroCells;
    w.step[a] = du[a].hi > 0.0 ? 1 : (du[a].hi < 0.0 ? -1 : 0);
  }
  for (int a = 0; a < 3; ++a) w.leave[a] = walk_exit(w, a);
  w.done = false;
  return w;
}

// The run from the current cell on; false once t_max was reached.
bool macro_next(inout MacroWalk w, DF t_max, out MacroRun run) {
  run = MacroRun(false, t_max);
  if (w.done) return false;
  if (p.skip == 0) {
    w.done = true;
    return true;
  }
  const ivec3 dims = ivec3(p.macro[0], p.macro[1], p.macro[2]);
  run.empty = macro_bit(w.m);
  for (;;) {
    // The face crossed first (the lower axis on ties).
    const int a = !df_less(w.leave[1], w.leave[0]) ? (!df_less(w.leave[2], w.leave[0]) ? 0 : 2)
                                                   : (!df_less(w.leave[2], w.leave[1]) ? 1 : 2);
    const DF leave = w.leave[a];
    w.m[a] += w.step[a];
    if (!df_less(leave, t_max) || w.m[a] < 0 || w.m[a] >= dims[a]) {
      w.done = true;
      return true;
    }
    w.leave[a] = walk_exit(w, a);
    if (macro_bit(w.m) != run.empty) {
      run.t_end = leave;
      return true;
    }
  }
  return true;  // (not reached)
}
