// The push constants every per-pixel march starts with (host/pixel_kernel.hpp,
// GridParams): the volume's layout, the rays of the dispatch and the early
// termination threshold, in double-float as the CPU compares it in double
// (in float it stopped rays the CPU went on with, 4e-3 off on neghip at
// --termination 0.99, issue 46). A shader's own parameters follow them:
//   layout(push_constant) uniform Params { GRID_PARAMS float h; ... } p;
#define GRID_PARAMS                                                            \
  uint sy, sz;        /* the volume's strides (samples per row, per slice) */  \
  int type;           /* grid_sampler.glsl's kUInt8 ... */                     \
  uint pixels;        /* rays in this dispatch */                              \
  float termination_lo; /* the threshold's low part (double-float) */        \
  float unused0, unused1; /* keep last_cell on 16 bytes */                     \
  uint row_pixels;    /* invocations per dispatch row (groups in x * 64) */    \
  ivec3 last_cell;    /* dims - 2 per axis */                                  \
  float termination;  /* transmittance threshold's high part, 0: off */      \
  uint part_shift;    /* log2 of a GpuArray part's bytes (split_array.glsl) */

// dims - 1 along axis a: the largest grid coordinate.
#define GRID_TOP(a) float(p.last_cell[a] + 1)
// The termination threshold as a double-float (double_float.glsl's DF).
#define GRID_TERMINATION DF(p.termination, p.termination_lo)

// This invocation's pixel, or a value >= p.pixels past the image's end.
#define PIXEL_INDEX() (gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * p.row_pixels)
