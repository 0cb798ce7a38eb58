// The packets' entry points in a build without them (src/core/simd.hpp:
// VRI_SIMD off, or not x86-64): packets_fit is false, so the integrators
// march ray by ray; should anything call a packet anyway, it gets the scalar
// march of each ray, which is what the packets' contract promises.
#include "core/simd.hpp"
#if !VRI_HAVE_AVX2_PACKETS
#include "methods/preint2_dual/dual_march.hpp"
#include "float_packet.hpp"
#include "methods/riemann/float_riemann.hpp"

namespace vri::detail {

bool packets_available() { return false; }

bool packets_fit(const GridVolume&) { return false; }

void march_preint1_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatLookup& table,
                          const DiscreteTf& tf, const FloatLighting& lighting, const Ray* rays, double h,
                          const Leap& leap, Rgba* out) {
  volume.visit([&](auto values) {
    for (int l = 0; l < kPacket; ++l)
      out[l] = march_float(volume, sampler, values.data(), table, tf, lighting, rays[l], h, leap);
  });
}

void march_preint2_packet(const GridVolume& volume, const FloatSampler& sampler, const SecondOrderFloatLookup& table,
                          const DiscreteTf& tf, const FloatLighting& lighting, const Ray* rays, double h,
                          const Leap& leap, Rgba* out) {
  volume.visit([&](auto values) {
    for (int l = 0; l < kPacket; ++l)
      out[l] = march_float(volume, sampler, values.data(), table, tf, lighting, rays[l], h, leap);
  });
}

void march_dual_packet(const GridVolume& volume, const DualFloatLookup& table, const FloatShading* shading,
                       bool interpolated, const Ray* rays, const Leap& leap, Rgba* out) {
  volume.visit([&](auto values) {
    for (int l = 0; l < kPacket; ++l)
      out[l] = march_cells_float(volume, values.data(), table, shading, interpolated, rays[l], leap);
  });
}

void march_riemann_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatTransferFunction& tf,
                          const FloatShading* shading, const Ray* rays, double h, const Leap& leap, Rgba* out) {
  volume.visit([&](auto values) {
    for (int l = 0; l < kPacket; ++l)
      out[l] = march_riemann_float(volume, sampler, values.data(), tf, shading, rays[l], h, leap);
  });
}

}  // namespace vri::detail
#endif  // !VRI_HAVE_AVX2_PACKETS
