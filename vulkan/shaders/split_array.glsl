// An array larger than one storage buffer may be (maxStorageBufferRange:
// 128 MiB on lavapipe) bound as up to four buffers of 2^p.part_shift bytes
// each, the last one shorter (host/gpu_array.hpp); bindings past the array's
// last part repeat it and are never read. ELEMENT_LOG2 is log2 of the
// element's bytes (vec4: 4, float and uint: 2). An input whose bit BIT of
// the specialization constant kSplitArrays is clear has one part and is read
// directly, the choice among parts compiled away when the pipeline is made
// (host/compute_kernel.hpp): chosen at run time, even on a uniform branch,
// it cost lavapipe a load from every part (marches 4x slower).
//   SPLIT_INPUT(vec4, table, 4, 4u, 2)    bindings 4 .. 7, declares table_at(i)
//   SPLIT_OUTPUT(vec4, entries, 0, 4u)    bindings 0 .. 3, declares entries_put(i, v)
// Needs before it: the push-constant block `p` with `uint part_shift`.
layout(constant_id = 0) const uint kSplitArrays = 0u;
#define SPLIT_BLOCKS(ACCESS, TYPE, NAME, FIRST)                                                         \
  layout(std430, binding = FIRST) ACCESS buffer NAME##Part0 { TYPE e[]; } NAME##_part0;                 \
  layout(std430, binding = FIRST + 1) ACCESS buffer NAME##Part1 { TYPE e[]; } NAME##_part1;             \
  layout(std430, binding = FIRST + 2) ACCESS buffer NAME##Part2 { TYPE e[]; } NAME##_part2;             \
  layout(std430, binding = FIRST + 3) ACCESS buffer NAME##Part3 { TYPE e[]; } NAME##_part3;
#define SPLIT_INPUT(TYPE, NAME, FIRST, ELEMENT_LOG2, BIT)                                               \
  SPLIT_BLOCKS(readonly, TYPE, NAME, FIRST)                                                             \
  TYPE NAME##_at(uint i) {                                                                              \
    if ((kSplitArrays & (1u << BIT)) == 0u) return NAME##_part0.e[i];                                   \
    const uint s = p.part_shift - ELEMENT_LOG2, k = i >> s, j = i & ((1u << s) - 1u);                   \
    return k == 0u   ? NAME##_part0.e[j]                                                            \
           : k == 1u ? NAME##_part1.e[j]                                                            \
           : k == 2u ? NAME##_part2.e[j]                                                            \
                     : NAME##_part3.e[j];                                                           \
  }
#define SPLIT_OUTPUT(TYPE, NAME, FIRST, ELEMENT_LOG2)                                                   \
  SPLIT_BLOCKS(writeonly, TYPE, NAME, FIRST)                                                            \
  void NAME##_put(uint i, TYPE v) {                                                                     \
    const uint s = p.part_shift - ELEMENT_LOG2, k = i >> s, j = i & ((1u << s) - 1u);                   \
    if (k == 0u) NAME##_part0.e[j] = v;                                                                 \
    else if (k == 1u) NAME##_part1.e[j] = v;                                                            \
    else if (k == 2u) NAME##_part2.e[j] = v;                                                            \
    else NAME##_part3.e[j] = v;                                                                         \
  }
