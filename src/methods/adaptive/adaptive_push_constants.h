// The push constants of adaptive.comp (coupled, decoupled) and
// adaptive_guaranteed.comp, one list each for their host renderers and
// kernels (vulkan/shaders/push_constants.h).
#include "push_constants.h"
#define VRI_ADAPTIVE_PUSH_CONSTANTS                                          \
  VRI_BLOCK(GridParams, grid, VRI_GRID_FIELDS)                               \
  VRI_BLOCK(TfParams, tf, VRI_TF_FIELDS)                                     \
  VRI_BLOCK(ShadingParams, shading, VRI_SHADING_FIELDS) /* lit 1: each sample lit */ \
  float tolerance, h0, hmin, hmax; /* world units */                         \
  VRI_INT coupled;                 /* 1: coupled, 0: decoupled */            \
  VRI_BLOCK(SkipParams, skip, VRI_SKIP_FIELDS)
#define VRI_ADAPTIVE_GUARANTEED_PUSH_CONSTANTS                               \
  VRI_BLOCK(GridParams, grid, VRI_GRID_FIELDS)                               \
  VRI_BLOCK(TfParams, tf, VRI_TF_FIELDS)                                     \
  VRI_BLOCK(ShadingParams, shading, VRI_SHADING_FIELDS) /* lit 1: each sample lit */ \
  float tolerance, hmax, hfloor; /* world units */                           \
  float margin;                  /* rounding of interpolated scalars (EmptySpace's) */ \
  VRI_BLOCK(SkipParams, skip, VRI_SKIP_FIELDS)
