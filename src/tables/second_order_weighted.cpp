#include "vri/tables/second_order_weighted.hpp"

#include "tables/second_order_substeps.hpp"

namespace vri {

SecondOrderWeights second_order_weighted_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b,
                                               double length, int iterations) {
  SecondOrderWeights out;
  double T = 1;
  detail::for_each_second_order_substep(tf, u_f, u_m, u_b, length, iterations, [&](double t, const SlabRgba& v) {
    const auto add = [&](SlabRgba& to, double w) {
      to.r += w * T * v.r, to.g += w * T * v.g, to.b += w * T * v.b, to.a += w * T * v.a;
    };
    add(out.front, lagrange_front(t));
    add(out.middle, lagrange_middle(t));
    add(out.back, lagrange_back(t));
    out.full = over(out.full, v);
    T *= 1 - v.a;
  });
  return out;
}

}  // namespace vri
