#include "riemann.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "methods/march/float_packet.hpp"
#include "float_riemann.hpp"
#include "vri/error.hpp"

namespace vri {

RiemannIntegrator::RiemannIntegrator(const GridVolume& volume, const TransferFunction& tf,
                                     double step, const Lighting& lighting, const FastPath& fast,
                                     std::optional<std::uint64_t> jitter)
    : volume_(volume),
      tf_(tf),
      fast_(volume, ZeroOpacity(tf), fast, "riemann"),
      float_path_(fast.float_math),
      float_sampler_(volume),
      float_tf_(tf),
      jitter_(jitter),
      packets_(float_path_ && !jitter && detail::packets_fit(volume)) {
  if (lighting.enabled) shader_.emplace(lighting, volume);
  if (lighting.enabled && float_path_)
    float_shading_ = std::make_unique<detail::FloatShading>(lighting, *shader_, float_sampler_);
  if (!(step >= 1e-4 && step <= 1e4))
    throw Error("riemann: step must be in [1e-4, 1e4] voxel units, got " + format_g(step));
  h_ = step * volume.voxel_unit();
}

RiemannIntegrator::~RiemannIntegrator() = default;

Rgba RiemannIntegrator::integrate(const Ray& ray) const {
  return volume_.visit([&](auto values) {
    if (float_path_)
      return detail::march_riemann_float(volume_, float_sampler_, values.data(), float_tf_, float_shading_.get(), ray,
                                         h_, {fast_.space(), fast_.termination()}, jitter_);
    return march(ray, values.data());
  });
}

template <class Value>
Rgba RiemannIntegrator::march(const Ray& ray, const Value* values) const {
  const auto iv = volume_.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  const double u = jitter_ ? detail::jitter_fraction(ray, *jitter_) : 0.0;  // the sample's place in its step
  const PieceRange owned = owned_pieces(*iv, h_, detail::riemann_samples(*iv, h_));
  double T = 1, C[3] = {0, 0, 0};
  const EmptySpace* space = fast_.space();
  detail::MacroRuns runs(space, ray, iv->t1);
  for (long long k = owned.begin; k < owned.end && !(T < fast_.termination()); ++k) {
    const double t_k = iv->t0 + k * h_;  // the step [t_k, t_k + hk]
    const double hk = std::min(h_, iv->t1 - t_k);
    if (!(hk > 0)) break;
    // The runs are asked where the sample lies (not at t_k: an empty run
    // that ends between t_k and the sample does not hold it).
    if (const double t_s = t_k + u * hk; space && t_s >= runs.end()) {
      const EmptySpace::Run run = runs.at(t_s);
      if (run.empty) {  // samples k .. up to run.t_end add nothing
        k = std::max(k, detail::last_sample_before(run.t_end, *iv, h_, u));
        continue;
      }
    }
    const Vec3 p = ray.at(t_k + u * hk);
    const TfSample v = tf_(volume_.sample(values, p));
    if (v.tau == 0) continue;
    const double a = -std::expm1(-v.tau * hk);  // 1 - exp(-tau h), accurate for small tau h
    const auto lit = shader_ ? shader_->at(p, ray.dir) : HeadlightShader::Terms{1, 0};
    C[0] += T * (v.r * lit.a + lit.b) * a;
    C[1] += T * (v.g * lit.a + lit.b) * a;
    C[2] += T * (v.b * lit.a + lit.b) * a;
    T *= 1 - a;
  }
  return {C[0], C[1], C[2], 1 - T};
}

void RiemannIntegrator::integrate_row(const Ray* rays, int n, Rgba* out) const {
  int i = 0;
  if (packets_) {
    const detail::Leap leap{fast_.space(), fast_.termination(), fast_.zero()};
    for (; i + detail::kPacket <= n; i += detail::kPacket)
      detail::march_riemann_packet(volume_, float_sampler_, float_tf_, float_shading_.get(), rays + i, h_, leap,
                                   out + i);
  }
  for (; i < n; ++i) out[i] = integrate(rays[i]);
}

std::unique_ptr<Integrator> make_riemann(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                         const Lighting& lighting) {
  return std::make_unique<RiemannIntegrator>(volume, tf, spec.step, lighting, spec.fast, spec.jitter);
}

}  // namespace vri
