#include "vri/analysis.hpp"

#include <algorithm>
#include <cmath>

#include "vri/error.hpp"
#include "volume/cell_traversal.hpp"

namespace vri {

RaySignal::RaySignal(const GridVolume& volume, const Ray& ray, std::optional<double> step)
    : volume_(volume), ray_(ray) {
  const auto iv = clip_to_box(ray, volume.box_lo(), volume.box_hi());
  if (!iv) throw Error("the ray misses the volume");
  if (step) {
    if (!(*step > 0) || !std::isfinite(*step)) throw Error("ray step must be a finite number > 0");
    // At least one interval (a step longer than the ray left none: issue 17),
    // and the count is bounded before the cast.
    const double intervals = std::max(1.0, std::ceil(iv->length() / *step));
    if (!(intervals <= 10'000'000)) throw Error("ray step is too small for this ray");
    const long long n = static_cast<long long>(intervals);
    for (long long k = 0; k < n; ++k) t_.push_back(iv->t0 + k * *step);
    t_.push_back(iv->t1);
  } else {
    t_.push_back(iv->t0);
    for_each_cell_segment(volume, ray, *iv, [&](const CellSegment& seg) {
      t_.push_back(0.5 * (seg.ta + seg.tb));
      t_.push_back(seg.tb);
      return true;
    });
  }
  for (double t : t_) s_.push_back(signal(t));
}

double RaySignal::signal(double t) const { return volume_.sample(ray_.at(t)); }

std::size_t RaySignal::interval(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  const std::size_t k = it == t_.begin() ? 0 : std::size_t(it - t_.begin()) - 1;
  return std::min(k, t_.size() - 2);
}

double RaySignal::approximation(int order, double t) const {
  const std::size_t k = interval(t);
  const double ta = t_[k], tb = t_[k + 1];
  if (order == 0) return t - ta < tb - t ? s_[k] : s_[k + 1];
  const std::size_t intervals = t_.size() - 1;
  if (order == 1 || (k == intervals - 1 && intervals % 2 == 1))
    return s_[k] + (s_[k + 1] - s_[k]) * (t - ta) / (tb - ta);
  // order 2: the parabola through the slab's front, middle and back samples,
  // in Lagrange form (exact for unequal spacing too).
  const std::size_t f = k - k % 2;
  const double x0 = t_[f], x1 = t_[f + 1], x2 = t_[f + 2];
  return s_[f] * (t - x1) * (t - x2) / ((x0 - x1) * (x0 - x2)) +
         s_[f + 1] * (t - x0) * (t - x2) / ((x1 - x0) * (x1 - x2)) +
         s_[f + 2] * (t - x0) * (t - x1) / ((x2 - x0) * (x2 - x1));
}

double RaySignal::xi(int order, int per_interval) const {
  double sum = 0;
  for (std::size_t k = 0; k + 1 < t_.size(); ++k) {
    const double h = (t_[k + 1] - t_[k]) / per_interval;
    for (int i = 0; i < per_interval; ++i) {
      const double t = t_[k] + (i + 0.5) * h;
      sum += std::abs(signal(t) - approximation(order, t)) * h;
    }
  }
  return sum;
}

}  // namespace vri
