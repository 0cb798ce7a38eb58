// The push constants every per-pixel march starts with (host/pixel_kernel.hpp,
// GridParams): the volume's layout, the rays of the dispatch and the early
// termination threshold. A shader's own parameters follow them:
//   layout(push_constant) uniform Params { GRID_PARAMS float h; ... } p;
#define GRID_PARAMS                                                            \
  uint sy, sz;        /* the volume's strides (samples per row, per slice) */  \
  int type;           /* grid_sampler.glsl's kUInt8 ... */                     \
  uint pixels;        /* rays in this dispatch */                              \
  vec3 top;           /* dims - 1 per axis */                                  \
  uint row_pixels;    /* invocations per dispatch row (groups in x * 64) */    \
  ivec3 last_cell;    /* dims - 2 per axis */                                  \
  float termination;  /* transmittance threshold, 0: off */                \
  uint part_shift;    /* log2 of a GpuArray part's bytes (split_array.glsl) */

// This invocation's pixel, or a value >= p.pixels past the image's end.
#define PIXEL_INDEX() (gl_GlobalInvocationID.x + gl_GlobalInvocationID.y * p.row_pixels)
