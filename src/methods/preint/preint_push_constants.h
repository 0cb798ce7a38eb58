// preint.comp's push constants (preint1 and preint2), one list for
// vulkan_preint.cpp and the kernel (vulkan/shaders/push_constants.h).
#include "push_constants.h"
#define VRI_PREINT_PUSH_CONSTANTS                    \
  VRI_BLOCK(GridParams, grid, VRI_GRID_FIELDS)       \
  VRI_BLOCK(TableParams, table, VRI_TABLE_FIELDS)    \
  VRI_BLOCK(ShadingParams, shading, VRI_SHADING_FIELDS) /* lit 1: sampled, 2: interpolated */ \
  VRI_BLOCK(SkipParams, skip, VRI_SKIP_FIELDS)
