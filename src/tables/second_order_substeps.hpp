#pragma once
// The sub-steps of one second-order entry (second_order_table.hpp; El Hajjar
// et al. 2008, Eq. 2 stepped as in their §6.2): sub-step k of K is the
// homogeneous segment of length L/K at the parabola's value at its midpoint
// t_k = (k + 1/2)/K (Horner, clamped to the axis), the transfer function
// linear between table scalars (DiscreteTf::between_samples: the second-order
// tables do not yet see control points inside a bin, issue 16). Shared by the unweighted
// and the weighted (second_order_weighted.hpp) definitions.
#include <algorithm>

#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/slab_integral.hpp"

namespace vri::detail {

// Calls visit(t_k, slab_k) for k = 0 .. K-1, front to back.
template <class Visit>
void for_each_second_order_substep(const DiscreteTf& tf, double u_f, double u_m, double u_b, double length,
                                   int iterations, Visit&& visit) {
  const double A = 2 * u_f - 4 * u_m + 2 * u_b, B = -3 * u_f + 4 * u_m - u_b, C = u_f;
  const double top = tf.size() - 1, step = length / iterations;
  for (int k = 0; k < iterations; ++k) {
    const double t = (k + 0.5) / iterations;
    const double u = std::clamp((A * t + B) * t + C, 0.0, top);
    visit(t, homogeneous_slab(tf.between_samples(u), step));
  }
}

}  // namespace vri::detail
