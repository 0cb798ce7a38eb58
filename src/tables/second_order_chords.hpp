#pragma once
// The chords of one second-order entry (second_order_table.hpp): the parabola
// P(t) = (A t + B) t + C of El Hajjar et al. 2008, Eq. 2, cut at t_j = j/K
// into K chords, chord k a linear ramp of the scalar from P(t_k) to
// P(t_{k+1}) (each clamped to the axis, SPEC §3) over a length L/K. Each chord
// is then integrated like a first-order slab, through every control point it
// crosses (integrate_slab), so a feature narrower than a table bin is never
// stepped over (issue 16). Shared by the unweighted and the weighted
// (second_order_weighted.hpp) definitions.
#include <algorithm>

#include "tables/discrete_tf.hpp"

namespace vri::detail {

// Calls visit(t_k, t_{k+1}, u_k, u_{k+1}, L/K) for k = 0 .. K-1, front to
// back; u are continuous table indices.
template <class Visit>
void for_each_second_order_chord(const DiscreteTf& tf, double u_f, double u_m, double u_b, double length,
                                 int iterations, Visit&& visit) {
  const double A = 2 * u_f - 4 * u_m + 2 * u_b, B = -3 * u_f + 4 * u_m - u_b, C = u_f;
  const double top = tf.size() - 1, step = length / iterations;
  const auto at = [&](int j) {
    const double t = double(j) / iterations;
    return std::clamp((A * t + B) * t + C, 0.0, top);
  };
  double u0 = at(0);
  for (int k = 0; k < iterations; ++k) {
    const double u1 = at(k + 1);
    visit(double(k) / iterations, double(k + 1) / iterations, u0, u1, step);
    u0 = u1;
  }
}

}  // namespace vri::detail
