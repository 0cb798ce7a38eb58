// tet_raycast.comp's push constants, one list for vulkan_tet_raycast.cpp and
// the kernel (vulkan/shaders/push_constants.h).
#include "push_constants.h"
#define VRI_TET_RAYCAST_PUSH_CONSTANTS                                                  \
  VRI_BLOCK(GridParams, grid, VRI_GRID_FIELDS) /* the dispatch's part and part_shift; no volume */ \
  VRI_BLOCK(TableParams, table, VRI_TABLE_FIELDS)                                       \
  VRI_BLOCK(ShadingParams, shading, VRI_SHADING_FIELDS) /* lit 1: sampled, 2: interpolated */ \
  float max_length; /* the tables' longest length (world units) */                     \
  VRI_INT lengths;  /* table slices */                                                  \
  VRI_INT tets;     /* the walk's bound, as the CPU's */                                \
  float extent;     /* the mesh box's diagonal: the scale of float roundings in t */
