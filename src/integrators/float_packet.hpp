#pragma once
// Packets of rays for preint1's unlit float path (issue 8;
// docs/PERFORMANCE.md, "Interactive speed"): kPacket rays marched together,
// their samples interpolated 8 at a time with AVX2 (gathers of the trilinear
// corners) while each ray keeps its own sample positions u0 + k du, leaps,
// table lookups, compositing and partial last slab, exactly as
// march_preint1_float (float_march.hpp) does them: the same bytes, ray by ray.
#include "ray_steps.hpp"
#include "vri/core/ray.hpp"
#include "vri/core/rgba.hpp"
#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/float_lookup.hpp"
#include "vri/volume/float_sampler.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri::detail {

inline constexpr int kPacket = 8;

// True where the CPU has AVX2 and the volume's and table's offsets fit the
// 32-bit gather indices; else the rays are marched one by one.
bool packets_fit(const FloatSampler& sampler, const FloatLookup& table, const GridVolume& volume);

// out[i] = march_preint1_float(..., rays[i], ...) for i < kPacket.
void march_preint1_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatLookup& table,
                          const DiscreteTf& tf, const Ray* rays, double h, const Leap& leap, Rgba* out);

}  // namespace vri::detail
