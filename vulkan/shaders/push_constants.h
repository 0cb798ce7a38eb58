// The kernels' push constants, one list for both sides: C++ (the renderers'
// Params structs) and GLSL (`layout(push_constant) uniform Params { ... } p;`)
// include this file, so a field cannot sit at one offset on the host and at
// another in the kernel. A method's block (its <method>_push_constants.h)
// lists fields and sub-blocks; VRI_BLOCK(Type, member, FIELDS) is a member
// of struct Type in C++ and the fields themselves in GLSL (push constants
// are one flat block there). Every field is 4 bytes and 4-aligned (int[3],
// not ivec3), so the C++ structs and GLSL's std430 block lay out alike.
#ifndef VRI_PUSH_CONSTANTS_H
#define VRI_PUSH_CONSTANTS_H

#ifdef __cplusplus
#include <cstdint>
#define VRI_INT std::int32_t
#define VRI_UINT std::uint32_t
#define VRI_BLOCK(Type, member, FIELDS) Type member;
#else
#define VRI_INT int
#define VRI_UINT uint
#define VRI_BLOCK(Type, member, FIELDS) FIELDS
#endif

// Every per-pixel march's first block (grid_params.glsl; pixel_kernel.hpp
// fills it): the volume's layout, the dispatch's rays, and the early
// termination threshold in double-float as the CPU compares it in double
// (in float it stopped rays the CPU went on with, 4e-3 off on neghip at
// --termination 0.99, issue 46).
#define VRI_GRID_FIELDS                                                                  \
  VRI_UINT sy, sz;      /* the volume's strides (samples per row, per slice) */          \
  VRI_INT type;         /* grid_sampler.glsl's kUInt8 ... */                              \
  VRI_UINT pixels;      /* rays in this dispatch */                                       \
  float termination_lo; /* the threshold's low part (double-float) */                     \
  VRI_UINT row_pixels;  /* invocations per dispatch row (groups in x * 64) */             \
  VRI_INT last_cell[3]; /* dims - 2 per axis */                                           \
  float termination;    /* the transmittance threshold's high part, 0: off */             \
  VRI_UINT part_shift;  /* log2 of a GpuArray part's bytes (split_array.glsl) */

// The transfer function (transfer_function.glsl; GpuTransferFunction).
#define VRI_TF_FIELDS float tf_lo, tf_scale; VRI_INT tf_bins, segments;

// Lighting (shading.glsl; shading_params): lit 0 off, else the method's mode.
#define VRI_SHADING_FIELDS VRI_INT lit; float ka, kd, ks, shininess, flat_threshold;

// Empty-space skipping (empty_space.glsl; GpuEmptySpace): 1 on, macro cells per axis.
#define VRI_SKIP_FIELDS VRI_INT skip; VRI_INT macro[3];

// A pre-integration table's axis (table_lookup.glsl): entries a side, its scalar map.
#define VRI_TABLE_FIELDS VRI_INT table_n; float table_lo, table_scale;

#ifdef __cplusplus
namespace vri::vulkan {
struct GridParams { VRI_GRID_FIELDS };
struct TfParams { VRI_TF_FIELDS };
struct ShadingParams { VRI_SHADING_FIELDS };
struct SkipParams { VRI_SKIP_FIELDS };
struct TableParams { VRI_TABLE_FIELDS };
}  // namespace vri::vulkan
#endif

#endif
