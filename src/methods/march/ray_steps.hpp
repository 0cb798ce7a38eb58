#pragma once
// Uniform ray stepping shared by the pre-integrated ray casters (preint1,
// preint2, lit or not): the ray clipped to the volume box is sampled at
// t0 + i h, cut into slabs of Samples - 1 steps (one table lookup each), and
// each slab's back sample is the next slab's front. The remaining length
// r < (Samples - 1) h is the partial slab: it is cut into Samples - 1 equal
// sub-slabs of length r / (Samples - 1) < h, which the slab policy integrates
// exactly under the table's discretisation with the scalar linear along each
// (exact_slab), so it is neither dropped nor counted twice and adds no length
// interpolation error.
//
// Leap (the fast path of preint1 and preint2, fast_path.hpp): the march jumps
// over runs of empty macro cells from slab front to slab front, so it stays on
// the same samples; every slab it skips has all its samples in the run and
// would read zero table entries (for preint2's parabolas because the cells
// were classified with TableOrder::Second, tables/zero_opacity.hpp). It stops
// once T < termination.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "vri/error.hpp"
#include "vri/geometry.hpp"
#include "volume/empty_space.hpp"
#include "volume/float_sampler.hpp"
#include "vri/volume.hpp"
#include "volume/transparent_cells.hpp"

namespace vri::detail {

// The step h in world units; `step` is in voxel units (1e-4 .. 1e4).
inline double world_step(const GridVolume& volume, double step, const std::string& method) {
  if (!(step >= 1e-4 && step <= 1e4))
    throw Error(method + ": step must be in [1e-4, 1e4] voxel units, got " + format_g(step));
  return step * volume.voxel_unit();
}

// Front-to-back compositing of premultiplied slabs, in double on every path.
// The float paths hand it their float slabs and samples: in float, C and T
// rounded once a slab, which over the thousands of slabs of a fine step grew
// to 4e-5 (engine, riemann h = 0.02, against --double), and a brick starting
// its part of a ray at T = 1 rounded differently from one process, 1.1e-6 on
// engine at 256^2 (issue 23 holds bricks to 1e-6). The AVX2 packets do these
// operations on 8 lanes (packet_lanes.hpp, composite8 and riemann_composite8).
struct FrontToBack {
  double T = 1, C[3] = {0, 0, 0};
  void add(double r, double g, double b, double a) {
    C[0] += T * r;
    C[1] += T * g;
    C[2] += T * b;
    T *= 1 - a;
  }
  // A Riemann step: colour (r, g, b) over a step of transparency e = e^{-tau h}.
  void add_step(double r, double g, double b, double e) {
    const double w = T * (1 - e);
    C[0] += w * r;
    C[1] += w * g;
    C[2] += w * b;
    T *= e;
  }
  Rgba result() const { return {C[0], C[1], C[2], 1 - T}; }
};

// One sample of the march: its scalar and what the slab policy keeps there
// (nothing, a gradient, shader terms).
template <class State>
struct SlabSample {
  double s;
  State state;
};

// Marches `ray` in slabs of Samples - 1 steps of h (world units) and
// composites what `policy` makes of them:
//   State at(Vec3 p)                                         what a sample carries
//   Rgba slab(const std::array<SlabSample<State>, Samples>&) a full slab, samples front to back
//   Rgba last(const SlabSample<State>& front, const SlabSample<State>& back, double length)
//                                                            one sub-slab of the partial slab
// Each sample is taken once and serves the slabs on both sides of it. The
// next slab's samples are taken before the current slab is composited and
// handed to prefetch(samples), so a large table can start loading its entries.
struct NoPrefetch {
  template <class S>
  void operator()(const S&) const {}
};

struct Leap {
  const EmptySpace* space = nullptr;  // null: no skipping
  double termination = 0;             // 0: never stop early
  // Pre-integrated methods with skipping: where the partial last slab's
  // scalars lie in a zero-opacity range it adds exactly nothing, so its exact
  // integral is not computed (the same bytes; null: always computed).
  const ZeroOpacity* zero = nullptr;
  // preint2-dual's float path: cells whose every segment reads zero entries
  // (their corners' range classified for second-order entries), not sampled.
  const TransparentCells* cells = nullptr;
};

// One ray's runs of empty and of non-empty macro cells, asked for front to
// back by the marches' leaps: one macro-cell walk a ray (EmptySpace::Walk,
// begun at the first query), not a fresh EmptySpace::run at each run
// boundary, which located its macro cell and the box of the non-empty ones
// again (a ray alternates between the two kinds a few times).
class MacroRuns {
 public:
  MacroRuns() = default;  // no skipping
  MacroRuns(const EmptySpace* space, const Ray& ray, double t_max) { start(space, ray, t_max); }
  // (Again) from the front of `ray`, which must outlive the queries (the walk holds it).
  void start(const EmptySpace* space, const Ray& ray, double t_max) {
    space_ = space, ray_ = &ray, t_max_ = t_max;
    last_ = {false, -std::numeric_limits<double>::infinity()};
    walk_.reset();
  }
  // The run that holds t. Queries go front to back: t lies in the run last
  // returned or after it.
  EmptySpace::Run at(double t) {
    if (t < last_.t_end) return last_;
    if (!walk_) walk_.emplace(*space_, *ray_, t, t_max_);
    EmptySpace::Run run;
    while (walk_->next(run))
      if (run.t_end > t) return last_ = run;
    return last_ = {false, t_max_};  // (past the walk, by rounding) marched
  }
  // The end of the run last returned (-inf before the first query): no query is due before it.
  double end() const { return last_.t_end; }
  bool skipping() const { return space_ != nullptr; }  // false: no runs to ask (skipping is off)

 private:
  const EmptySpace* space_ = nullptr;
  const Ray* ray_ = nullptr;
  double t_max_ = 0;
  EmptySpace::Run last_{false, -std::numeric_limits<double>::infinity()};
  std::optional<EmptySpace::Walk> walk_;
};

// From slab k of `steps` steps of h (its front sample at t = t0 + k steps h,
// k < full): the slab the march may leap to, j > k when the ray stands in a
// run of empty macro cells (samples k steps .. i lie in the run, and slabs
// k .. j - 1, whose samples are among them, read zero entries), else k.
// Queries `runs` (the ray's) only once t passes the end of the last run found.
inline long long leap_target(MacroRuns& runs, const Interval& iv, double h, int steps, long long k, long long full) {
  const double t = iv.t0 + k * steps * h;
  if (!runs.skipping() || t < runs.end()) return k;
  const EmptySpace::Run run = runs.at(t);
  const long long i = static_cast<long long>(std::floor((run.t_end - iv.t0) / h));
  return run.empty ? std::min(full, i / steps) : k;
}

// The march on the volume's typed samples `values` (GridVolume::visit, once
// per ray, so that no sample dispatches on the type).
template <int Samples, class Policy, class Prefetch, class Value>
Rgba march_typed(const GridVolume& volume, const Ray& ray, double h, const Policy& policy, Prefetch&& prefetch,
                 const Leap& leap, const Value* values) {
  static_assert(Samples >= 2);
  constexpr int steps = Samples - 1;
  const auto iv = volume.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  const double slab = steps * h;
  const long long all = static_cast<long long>(std::floor(iv->length() / slab));
  // The owned slabs (a brick's, else all): full ones begin .. full - 1, and
  // the partial slab (piece `all`) where end passes all.
  const PieceRange owned = owned_pieces(*iv, slab, all + 1);
  const long long full = std::min(owned.end, all);
  using Sample = SlabSample<decltype(policy.at(Vec3{}))>;
  using Slab = std::array<Sample, Samples>;
  const auto sample_at = [&](double t) {
    const Vec3 p = ray.at(t);
    return Sample{volume.sample(values, p), policy.at(p)};
  };
  const auto fill = [&](Slab& s, long long k) {
    for (int i = 1; i < Samples; ++i) s[i] = sample_at(iv->t0 + (k * steps + i) * h);
  };
  FrontToBack acc;
  Slab s{}, next{};
  s[0] = sample_at(iv->t0 + owned.begin * steps * h);
  if (owned.begin < full) fill(s, owned.begin);
  MacroRuns runs(leap.space, ray, iv->t1);
  for (long long k = owned.begin; k < full; ++k) {
    if (acc.T < leap.termination) return acc.result();
    if (const long long j = leap_target(runs, *iv, h, steps, k, full); j > k) {
      k = j;
      s[0] = sample_at(iv->t0 + k * steps * h);
      if (k == full) break;
      fill(s, k);
    }
    next[0] = s[steps];
    if (k + 1 < full) {
      fill(next, k + 1);
      prefetch(next);
    }
    const Rgba v = policy.slab(s);
    acc.add(v[0], v[1], v[2], v[3]);
    s = next;
  }
  if (acc.T < leap.termination || !(owned.begin <= all && all < owned.end)) return acc.result();
  const double t_rest = iv->t0 + full * steps * h;
  const double sub = (iv->t1 - t_rest) / steps;
  if (sub > 0)
    for (int i = 1; i <= steps; ++i) {
      const Sample back = sample_at(i == steps ? iv->t1 : t_rest + i * sub);
      const Rgba v = policy.last(s[0], back, sub);
      acc.add(v[0], v[1], v[2], v[3]);
      s[0] = back;
    }
  return acc.result();
}

template <int Samples, class Policy, class Prefetch = NoPrefetch>
Rgba march_uniform_slabs(const GridVolume& volume, const Ray& ray, double h, const Policy& policy,
                         Prefetch&& prefetch = {}, const Leap& leap = {}) {
  return volume.visit(
      [&](auto values) { return march_typed<Samples>(volume, ray, h, policy, prefetch, leap, values.data()); });
}

}  // namespace vri::detail
