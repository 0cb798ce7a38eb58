// riemann.comp's push constants, one list for vulkan_riemann.cpp and the
// kernel (vulkan/shaders/push_constants.h).
#include "push_constants.h"
#define VRI_RIEMANN_PUSH_CONSTANTS                  \
  VRI_BLOCK(GridParams, grid, VRI_GRID_FIELDS)      \
  float h; /* the step, world units */              \
  VRI_BLOCK(TfParams, tf, VRI_TF_FIELDS)            \
  VRI_BLOCK(ShadingParams, shading, VRI_SHADING_FIELDS) /* lit 1: each sample lit */ \
  VRI_BLOCK(SkipParams, skip, VRI_SKIP_FIELDS)
