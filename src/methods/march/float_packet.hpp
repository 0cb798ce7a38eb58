#pragma once
// Packets of rays for the float paths of riemann, preint1, preint2 and preint2-dual, unlit and
// lit (issues 8 and 21;
// docs/PERFORMANCE.md, "Float paths and packets"): kPacket neighbouring rays
// marched together with AVX2, one ray a lane. Each lane keeps its own sample
// positions u0 + i du, leaps (its own macro-cell queries) and partial last
// slab; per slab the 8 lanes' new samples are interpolated, placed on the
// table axis, looked up and composited as 8-lane vectors with the operations
// of march_float (float_march.hpp) in the same order, and no FMA (the kernel
// is compiled for AVX2 alone): the same bytes, ray by ray. Only on x86-64
// with VRI_SIMD (src/core/simd.hpp; float_packet_scalar.cpp otherwise).
#include "methods/preint/float_march.hpp"
#include "float_shading.hpp"
#include "ray_steps.hpp"
#include "vri/geometry.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/float_lookup.hpp"
#include "tables/second_order_float_lookup.hpp"
#include "transfer/float_transfer_function.hpp"
#include "volume/float_sampler.hpp"
#include "vri/volume.hpp"

namespace vri::detail {

inline constexpr int kPacket = 8;

class DualFloatLookup;  // dual_march.hpp

// True where the build has the AVX2 packets (src/core/simd.hpp) and the CPU
// has AVX2; else every march_*_packet is the scalar march, ray by ray.
bool packets_available();
// packets_available() and the volume's offsets fit 32-bit lanes; else the
// integrators march the rays one by one.
bool packets_fit(const GridVolume& volume);

// out[i] = march_float(..., table, ..., rays[i], ...) for i < kPacket.
// `lighting`: unlit, sampled or interpolated (float_march.hpp).
void march_preint1_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatLookup& table,
                          const DiscreteTf& tf, const FloatLighting& lighting, const Ray* rays, double h,
                          const Leap& leap, Rgba* out);
void march_preint2_packet(const GridVolume& volume, const FloatSampler& sampler, const SecondOrderFloatLookup& table,
                          const DiscreteTf& tf, const FloatLighting& lighting, const Ray* rays, double h,
                          const Leap& leap, Rgba* out);
// out[i] = march_cells_float(..., table, shading, interpolated, rays[i], leap)
// for i < kPacket: preint2-dual's float path (dual_march.hpp, float_packet_dual.cpp).
void march_dual_packet(const GridVolume& volume, const DualFloatLookup& table, const FloatShading* shading,
                       bool interpolated, const Ray* rays, const Leap& leap, Rgba* out);
// out[i] = march_riemann_float(..., rays[i], ...) for i < kPacket (float_riemann.hpp).
// `shading`: null unlit (float_shading.hpp).
void march_riemann_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatTransferFunction& tf,
                          const FloatShading* shading, const Ray* rays, double h, const Leap& leap, Rgba* out);

}  // namespace vri::detail
