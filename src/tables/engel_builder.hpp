#pragma once
// EngelBuilder: the O(N^2) approximation of Engel, Kraus & Ertl 2001 (their
// eqs. for the "neglected self-attenuation" table, as summarised by Lum,
// Wilson & Ma 2004, §4.2): inside a slab the colour is not attenuated,
//   C     ~ l / (s_b - s_f) * int_{s_f}^{s_b} tau(s) c(s) ds,
//   alpha = 1 - exp(-l / (s_b - s_f) * int_{s_f}^{s_b} tau(s) ds),
// both from prefix integrals of the discretised transfer function (exact for
// its piecewise-linear tau and quadratic tau*c). The diagonal is C = c tau l.
// Its error against `brute` is measured in docs/PREINTEGRATION.md.
#include "tables/table_builder.hpp"

namespace vri {

class EngelBuilder final : public TableBuilder {
 public:
  std::string_view name() const override { return "engel"; }
  // O(n^2): each entry from the integral functions.
  double work(int n) const override { return 4.0 * n * n; }
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;
};

}  // namespace vri
