// preint2_dual.comp's push constants, one list for vulkan_preint2_dual.cpp
// and the kernel (vulkan/shaders/push_constants.h).
#include "push_constants.h"
#define VRI_PREINT2_DUAL_PUSH_CONSTANTS                                                  \
  VRI_BLOCK(GridParams, grid, VRI_GRID_FIELDS)                                           \
  VRI_BLOCK(TableParams, table, VRI_TABLE_FIELDS)                                        \
  VRI_BLOCK(ShadingParams, shading, VRI_SHADING_FIELDS) /* lit 1: sampled, 2: interpolated */ \
  float max_length; /* world units: the longest in-cell chord */                         \
  VRI_INT lengths;  /* table slices */                                                   \
  VRI_BLOCK(SkipParams, skip, VRI_SKIP_FIELDS)
