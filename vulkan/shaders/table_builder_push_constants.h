// The table builders' push constants (sliced_table.comp,
// incremental_table.comp, second_order_table.comp), one list each for the
// kernels and vulkan/host/vulkan_table_builders.cpp (push_constants.h).
#include "push_constants.h"
#define VRI_SLICED_TABLE_PUSH_CONSTANTS                                         \
  VRI_UINT part_shift; /* split_array.glsl */                                   \
  VRI_INT table_n;     /* entries a side */                                     \
  VRI_INT steps;       /* n */                                                  \
  float dl;            /* l / n, world units */                                 \
  VRI_UINT base;       /* this length's first entry (a table of several lengths) */
#define VRI_INCREMENTAL_TABLE_PUSH_CONSTANTS                                    \
  VRI_UINT part_shift; /* split_array.glsl */                                   \
  VRI_INT table_n;     /* entries a side, N */                                  \
  float slab_length;   /* world units */
#define VRI_SECOND_ORDER_TABLE_PUSH_CONSTANTS                                   \
  VRI_UINT part_shift; /* split_array.glsl */                                   \
  VRI_INT table_n;     /* entries a side */                                     \
  VRI_INT iterations;  /* K */
