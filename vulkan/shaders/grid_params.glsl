// Helpers over the grid block every per-pixel march's push constants start
// with (push_constants.h, VRI_GRID_FIELDS; the host's GridParams).

// dims - 1 along axis a: the largest grid coordinate.
#define GRID_TOP(a) float(p.last_cell[a] + 1)
// The termination threshold as a double-float (double_float.glsl's DF).
#define GRID_TERMINATION DF(p.termination, p.termination_lo)

// This invocation's pixel, or a value >= p.pixels past the image's end.
#define PIXEL_INDEX() (gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * p.row_pixels)
