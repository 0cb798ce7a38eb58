#include "vri/integrators/preint1.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "preint1_slabs.hpp"
#include "ray_steps.hpp"
#include "vri/core/error.hpp"
#include "vri/tables/slab_integral.hpp"
#include "vri/tables/table_builder.hpp"

namespace vri {

Preint1Integrator::Preint1Integrator(const GridVolume& volume, const TransferFunction& tf, double step,
                                     int table_size, const std::string& builder, const Lighting& lighting,
                                     const FastPath& fast)
    : volume_(volume),
      h_(detail::world_step(volume, step, "preint1")),
      tf_(tf, table_size),
      table_(make_table_builder(builder)->build(tf_, h_)),
      fast_(volume, ZeroOpacity(tf_), fast, "preint1") {
  if (!lighting.enabled) return;
  if (lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error("preint1: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  shader_.emplace(lighting, volume);
  if (lighting.mode == "interpolated") weighted_.emplace(build_weighted_tables(tf_, h_));
}

template <class Policy>
Rgba Preint1Integrator::march(const Ray& ray, const Policy& policy) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const long long full = static_cast<long long>(std::floor(iv->length() / h_));
  double T = 1, C[3] = {0, 0, 0};
  const auto composite = [&](const Rgba& v) {
    C[0] += T * v[0];
    C[1] += T * v[1];
    C[2] += T * v[2];
    T *= 1 - v[3];
  };
  const EmptySpace* space = fast_.space();
  double t_check = -std::numeric_limits<double>::infinity();  // in a non-empty macro cell until then
  Vec3 p = ray.at(iv->t0);
  double s_front = volume_.sample(p);
  auto front = policy.at(p);
  // k: the front sample of the next slab.
  for (long long k = 0; k < full; ++k) {
    if (T < fast_.termination()) return {C[0], C[1], C[2], 1 - T};
    const double t = iv->t0 + k * h_;
    if (space && t >= t_check) {
      const EmptySpace::Run run = space->run(ray, t, iv->t1);
      if (run.empty) {  // the slabs between samples k .. j read zero entries
        const long long j = std::min(full, static_cast<long long>(std::floor((run.t_end - iv->t0) / h_)));
        if (j > k) {
          k = j;
          p = ray.at(iv->t0 + k * h_);
          s_front = volume_.sample(p);
          front = policy.at(p);
          if (k == full) break;
        }
      }
      t_check = run.t_end;
    }
    p = ray.at(iv->t0 + (k + 1) * h_);
    const double s_back = volume_.sample(p);
    const auto back = policy.at(p);
    composite(policy.slab(front, back, s_front, s_back));
    s_front = s_back;
    front = back;
  }
  if (T < fast_.termination()) return {C[0], C[1], C[2], 1 - T};
  const double rest = iv->t1 - (iv->t0 + full * h_);
  if (rest > 0) {
    p = ray.at(iv->t1);
    composite(policy.last(front, policy.at(p), s_front, volume_.sample(p), rest));
  }
  return {C[0], C[1], C[2], 1 - T};
}

Rgba Preint1Integrator::integrate(const Ray& ray) const {
  if (weighted_) return march(ray, preint1::Interpolated{*weighted_, tf_, *shader_, ray.dir});
  if (shader_) return march(ray, preint1::Sampled{table_, tf_, *shader_, ray.dir});
  return march(ray, preint1::Unlit{table_, tf_});
}

}  // namespace vri
