#include "ray_setup.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "methods/riemann/float_riemann.hpp"  // riemann_samples, jitter_fraction
#include "vri/error.hpp"
#include "tables/slab_integral.hpp"
#include "volume/float_sampler.hpp"

namespace vri::vulkan {

namespace {

// x as the double-float hi + lo, hi at out[0] and lo at out[lo_at].
void put(float* out, double x, int lo_at) {
  const float hi = static_cast<float>(x);
  out[0] = hi;
  out[lo_at] = static_cast<float>(x - static_cast<double>(hi));
}

// The span's rays, `floats` each: f(x, y, ray) for each pixel (x, y) of it,
// on `threads` threads (0: every core); a ray starts as zeros.
template <class Pixel>
std::vector<float> rays_of(const Camera& camera, PixelSpan span, int floats, int threads, const Pixel& pixel) {
  std::vector<float> out(span.count * static_cast<std::size_t>(floats), 0.0f);
  const auto width = static_cast<std::size_t>(camera.width());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);  // as render() does
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, span.count, 256),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i) {
                          const std::size_t p = span.first + i;
                          pixel(static_cast<int>(p % width), static_cast<int>(p / width), out.data() + i * floats);
                        }
                      });
  });
  return out;
}

void put_direction(float* out, const Ray& ray) {
  const auto d = detail::direction(ray);
  for (int a = 0; a < 3; ++a) out[a] = d[a];
}

// A count as the float whose bits are its int32 (the shaders read it with floatBitsToInt).
float count_bits(long long n) {
  return std::bit_cast<float>(static_cast<std::int32_t>(std::min<long long>(n, INT32_MAX)));
}

}  // namespace

std::vector<float> riemann_rays(const Camera& camera, const GridVolume& volume, double h,
                                std::optional<std::uint64_t> jitter, PixelSpan pixels, int threads) {
  const FloatSampler sampler(volume);
  return rays_of(camera, pixels, kRiemannRayFloats, threads, [&](int x, int y, float* r) {
    const Ray ray = camera.ray(x, y);
    const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
    if (!iv) return;  // no samples: transparent
    const double u = jitter ? detail::jitter_fraction(ray, *jitter) : 0.0;
    long long n = detail::riemann_samples(*iv, h);
    // The CPU stops at the first step with h_k <= 0 (a ray that only grazes the box).
    double h_last = std::min(h, iv->t1 - (iv->t0 + static_cast<double>(n - 1) * h));
    if (!(h_last > 0)) {
      --n;
      h_last = n > 0 ? std::min(h, iv->t1 - (iv->t0 + static_cast<double>(n - 1) * h)) : 0.0;
    }
    if (n <= 0) return;
    const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
    for (int a = 0; a < 3; ++a) {
      put(r + a, u0[a], 3);
      put(r + 6 + a, du[a], 3);
    }
    put(r + 12, u, 1);
    put(r + 14, h_last < h ? u * h_last / h : u, 1);
    r[16] = static_cast<float>(h_last);
    r[17] = count_bits(n);
    put_direction(r + 18, ray);
  });
}

std::vector<float> entry_rays(const Camera& camera, const GridVolume& volume, PixelSpan pixels, int threads) {
  const FloatSampler sampler(volume);
  return rays_of(camera, pixels, kEntryRayFloats, threads, [&](int x, int y, float* r) {
    const Ray ray = camera.ray(x, y);
    const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
    r[12] = -1;
    if (!iv) return;
    const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir);
    for (int a = 0; a < 3; ++a) {
      put(r + a, u0[a], 3);
      put(r + 6 + a, du[a], 3);
    }
    put(r + 12, iv->length(), 1);
    put_direction(r + 14, ray);
  });
}

std::vector<float> slab_rays(int steps, const Camera& camera, const GridVolume& volume, const DiscreteTf& tf,
                             const detail::FloatLighting& lighting, double h, PixelSpan pixels, int threads) {
  if (steps != 1 && steps != 2) throw Error("vulkan: slabs of 1 or 2 steps, not " + std::to_string(steps));
  const FloatSampler sampler(volume);
  return volume.visit([&](auto values) {
    return rays_of(camera, pixels, slab_ray_floats(steps), threads, [&](int x, int y, float* r) {
      const Ray ray = camera.ray(x, y);
      const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
      if (!iv) {
        r[12] = count_bits(-1);
        return;
      }
      // As march_float and finish_float (float_march.hpp).
      const long long full = static_cast<long long>(std::floor(iv->length() / (steps * h)));
      const Vec3 u0 = sampler.grid(ray.at(iv->t0)), du = sampler.grid_step(ray.dir * h);
      for (int a = 0; a < 3; ++a) {
        put(r + a, u0[a], 3);
        put(r + 6 + a, du[a], 3);
      }
      r[12] = count_bits(full);
      put_direction(r + 13 + 8 * steps, ray);
      const detail::FloatSample front = detail::sample_at(sampler, values.data(), lighting, detail::direction(ray),
                                                          u0 + static_cast<double>(full * steps) * du);
      const auto put_slabs = [&](const auto& slabs) {
        for (std::size_t i = 0; i < slabs.size(); ++i) {
          const SlabRgba& s = slabs[i];
          const double v[4] = {s.r, s.g, s.b, s.a};
          for (int c = 0; c < 4; ++c) put(r + 13 + 4 * i + c, v[c], 4 * steps);
        }
      };
      if (steps == 1)
        put_slabs(detail::last_slabs<1>(sampler, values.data(), tf, lighting, ray, *iv, full, h, front));
      else
        put_slabs(detail::last_slabs<2>(sampler, values.data(), tf, lighting, ray, *iv, full, h, front));
    });
  });
}

std::vector<float> mesh_rays(const Camera& camera, const TetMesh& mesh, Vec3 centre, PixelSpan pixels, int threads) {
  const Vec3 pad = (mesh.box_hi() - mesh.box_lo()) * 1e-3;
  return rays_of(camera, pixels, kMeshRayFloats, threads, [&](int x, int y, float* r) {
    const Ray ray = camera.ray(x, y);
    const auto iv = clip_to_box(ray, mesh.box_lo() - pad, mesh.box_hi() + pad);
    r[6] = -1;
    if (!iv) return;
    const Vec3 o = ray.at(std::max(iv->t0, 0.0)) - centre;
    for (int a = 0; a < 3; ++a) r[a] = static_cast<float>(o[a]);
    put_direction(r + 3, ray);
    r[6] = 1;
  });
}

}  // namespace vri::vulkan
