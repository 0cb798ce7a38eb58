#include "methods/march/float_packet.hpp"

#include "core/simd.hpp"
// riemann's AVX2 packets (march_riemann_float of float_riemann.hpp on 8
// rays), compiled where simd.hpp allows them; float_packet_scalar.cpp is
// the build without. The lanes' primitives are packet_lanes.hpp's.
#if VRI_HAVE_AVX2_PACKETS
#include "methods/march/packet_lanes.hpp"

namespace vri::detail {

using namespace lanes8;

namespace {

// Each ray's state for riemann, a lane each: what march_riemann_float keeps in locals.
struct RiemannLanes : RayLanes {
  alignas(32) double t0[kPacket], t1[kPacket];  // the clipped ray
  alignas(32) int k[kPacket], stop[kPacket];
  long long n[kPacket];
};

// FloatTransferFunction::operator() of 8 scalars: the bin's segment, the
// walk to the segment that holds each scalar (both ways, lanes as masks),
// then ref + slope (s - s_ref) per channel.
VRI_AVX2 void transfer8(const FloatTransferFunction& tf, __m256 s, __m256 v[4]) {
  const __m256 u = _mm256_min_ps(_mm256_max_ps(_mm256_mul_ps(_mm256_sub_ps(s, _mm256_set1_ps(tf.lo())),
                                                             _mm256_set1_ps(tf.scale())),
                                               _mm256_setzero_ps()),
                                 _mm256_set1_ps(static_cast<float>(FloatTransferFunction::kBins - 1)));
  __m256i i = _mm256_i32gather_epi32(tf.first(), _mm256_cvttps_epi32(u), 4);
  const float* bp = tf.breakpoints();
  for (;;) {  // up while breakpoint i <= s (the last breakpoint is +inf)
    const __m256i up = _mm256_castps_si256(_mm256_cmp_ps(_mm256_i32gather_ps(bp, i, 4), s, _CMP_LE_OQ));
    if (_mm256_testz_si256(up, up)) break;
    i = _mm256_sub_epi32(i, up);
  }
  for (;;) {  // down while i > 0 and breakpoint i - 1 > s
    const __m256i below = _mm256_max_epi32(_mm256_sub_epi32(i, _mm256_set1_epi32(1)), _mm256_setzero_si256());
    const __m256i down = _mm256_and_si256(_mm256_cmpgt_epi32(i, _mm256_setzero_si256()),
                                          _mm256_castps_si256(_mm256_cmp_ps(_mm256_i32gather_ps(bp, below, 4), s, _CMP_GT_OQ)));
    if (_mm256_testz_si256(down, down)) break;
    i = _mm256_add_epi32(i, down);
  }
  const __m256 ds = _mm256_sub_ps(s, _mm256_i32gather_ps(tf.s_ref(), i, 4));
  for (int c = 0; c < 4; ++c)
    v[c] = _mm256_add_ps(_mm256_i32gather_ps(tf.value(c), i, 4), _mm256_mul_ps(_mm256_i32gather_ps(tf.slope(c), i, 4), ds));
}

}  // namespace

// riemann's float path on 8 rays (march_riemann_float, float_riemann.hpp).
template <class Value>
__attribute__((target("avx2"))) void march_riemann_lanes(const GridVolume& volume, const FloatSampler& sampler,
                                                         const Value* values, const FloatTransferFunction& tf,
                                                         const FloatShading* shading, const Ray* rays, double h,
                                                         const Leap& leap, Rgba* out) {
  RiemannLanes L{};  // lanes without a ray read cell 0
  unsigned active = enter(L, volume, sampler, rays, h, out);
  for (unsigned m = active; m; m &= m - 1) {
    const int l = __builtin_ctz(m);
    L.t0[l] = L.iv[l].t0, L.t1[l] = L.iv[l].t1;
    const PieceRange owned = owned_pieces(L.iv[l], h, riemann_samples(L.iv[l], h));  // a brick's, else all
    L.k[l] = static_cast<int>(owned.begin);
    L.n[l] = owned.end;
    L.runs[l].start(leap.space, rays[l], L.iv[l].t1);
  }
  const auto finish = [&](int l) {
    out[l] = L.pixel(l);
    active &= ~(1u << l);
  };

  const __m256d hd = _mm256_set1_pd(h);
  while (active) {
    // Lanes at their stop: a leap and the next stop, or the end.
    const unsigned before_stop = mask(_mm256_cmpgt_epi32(load(L.stop), load(L.k)));
    for (unsigned m = active & ~before_stop; m; m &= m - 1) {
      const int l = __builtin_ctz(m);
      long long k = L.k[l];
      L.stop[l] = static_cast<int>(riemann_head(L.runs[l], L.iv[l], h, L.n[l], k));
      L.k[l] = static_cast<int>(std::min(k, L.n[l]));
      if (k >= L.n[l]) finish(l);
    }
    // h_k = min(h, t1 - t_k) in double; a lane ends below the termination
    // threshold or where h_k is not positive.
    const __m256i k = load(L.k);
    __m128 hk[2];
    unsigned positive = 0;
    for (int half = 0; half < 2; ++half) {
      const __m256d kd = _mm256_cvtepi32_pd(half ? _mm256_extracti128_si256(k, 1) : _mm256_castsi256_si128(k));
      const __m256d t = _mm256_add_pd(_mm256_load_pd(L.t0 + 4 * half), _mm256_mul_pd(kd, hd));
      const __m256d h_k = _mm256_min_pd(_mm256_sub_pd(_mm256_load_pd(L.t1 + 4 * half), t), hd);
      positive |= static_cast<unsigned>(_mm256_movemask_pd(_mm256_cmp_pd(h_k, _mm256_setzero_pd(), _CMP_GT_OQ))) << (4 * half);
      hk[half] = _mm256_cvtpd_ps(h_k);
    }
    const unsigned below = below8(L, leap.termination);
    for (unsigned m = active & (below | ~positive); m; m &= m - 1) finish(__builtin_ctz(m));
    if (!active) break;
    // Sample k of every lane, classified and composited (riemann_step).
    __m256 v[4];
    Cells8 cells;
    transfer8(tf, sample8(sampler, values, L, k, &cells), v);
    // The lit colour c a + b (riemann_step), unless no lane has opacity (a
    // step with tau = 0 adds exactly nothing whatever its colour).
    if (shading && _mm256_movemask_ps(_mm256_cmp_ps(v[3], _mm256_setzero_ps(), _CMP_NEQ_OQ))) {
      __m256 g[3], a, b;
      const __m256 d[3] = {load(L.d[0]), load(L.d[1]), load(L.d[2])};
      gradient8(*shading, cells, g);
      terms8(*shading, g, d, a, b);
      for (int c = 0; c < 3; ++c) v[c] = _mm256_add_ps(_mm256_mul_ps(v[c], a), b);
    }
    const __m256 e = exp_neg8(_mm256_mul_ps(v[3], _mm256_set_m128(hk[1], hk[0])));
    riemann_composite8(L, v, e);
    store(L.k, _mm256_add_epi32(k, _mm256_set1_epi32(1)));
  }
}

void march_riemann_packet(const GridVolume& volume, const FloatSampler& sampler, const FloatTransferFunction& tf,
                          const FloatShading* shading, const Ray* rays, double h, const Leap& leap, Rgba* out) {
  volume.visit(
      [&](auto values) { march_riemann_lanes(volume, sampler, values.data(), tf, shading, rays, h, leap, out); });
}

#undef VRI_AVX2

}  // namespace vri::detail
#endif  // VRI_HAVE_AVX2_PACKETS
