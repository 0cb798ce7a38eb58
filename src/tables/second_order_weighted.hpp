#pragma once
// Weighted second-order tables for interpolated lighting of preint2 (issue 5,
// item 3): Lum, Wilson & Ma 2004's weighted pre-integration (§3, their linear
// front/back weights) carried to El Hajjar et al. 2008's parabolic slabs with
// three weights, the quadratic Lagrange basis on the slab's front, middle and
// back sample (u in [0, 1] along the slab):
//
//   L_f(u) = (1 - u)(1 - 2u),   L_m(u) = 4u(1 - u),   L_b(u) = u(2u - 1),   L_f + L_m + L_b = 1,
//
//   diffuse  D_k = int L_k(u) c tau T dt   (the transfer function's colour)
//   specular S_k = int L_k(u) tau T dt     (white),
//
// so D_f + D_m + D_b = C and S_f + S_m + S_b = alpha of the unweighted slab.
// In the table's model (second_order_table.hpp: K chords from P(t_k) to
// P(t_{k+1}), t_j = j/K) each weight is taken linear across a chord: chord k's
// integrals weighted by its own front and back weight (weighted_tables.hpp,
// integrated exactly through the control points) count with L(t_k) and
// L(t_{k+1}), times the transmittance in front of the chord. So the weighted
// entries converge to the integrals above as O(1/K^2), like the unweighted ones.
//
// Packing: three RGBA tables of N^3 entries,
//   full = (C, alpha)  (the unweighted table, the same bytes as the builder's build()),
//   middle = (D_m, S_m),   back = (D_b, S_b),
// and D_f = C - D_m - D_b, S_f = alpha - S_m - S_b. L_f and L_b dip below 0,
// so D_f, D_b can be negative: the tables are signed floats.
// Memory: 3 N^3 x 16 bytes, 768 MiB at N = 256 (within kMaxSecondOrderEntries).
#include "tables/second_order_table.hpp"

namespace vri {

struct SecondOrderWeightedTables {
  // Three all-zero tables (SecondOrderTable's refusals apply).
  SecondOrderWeightedTables(const ScalarAxis& axis, double length, int iterations)
      : full(axis, length, iterations), middle(axis, length, iterations), back(axis, length, iterations) {}
  SecondOrderTable full, middle, back;  // packed as above
};

// The quadratic Lagrange basis on u = 0, 1/2, 1.
inline double lagrange_front(double u) { return (1 - u) * (1 - 2 * u); }
inline double lagrange_middle(double u) { return 4 * u * (1 - u); }
inline double lagrange_back(double u) { return u * (2 * u - 1); }

// One slab's integrals, unpacked: rgb = D_k, a = S_k for k = front, middle,
// back, and the unweighted slab (the same value as second_order_entry).
struct SecondOrderWeights {
  SlabRgba front, middle, back, full;
};

// One entry of the weighted model above at continuous indices, in double
// precision: the definition the builders' build_weighted() is held to.
SecondOrderWeights second_order_weighted_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b,
                                               double length, int iterations);

// preint2-dual's (l, s_f, s_m, s_b) tables with the weights: M slices of each
// packed table, at the lengths of build_second_order_length_table (3x its
// memory: 384 MiB at N = 64, M = 32).
struct SecondOrderWeightedLengthTables {
  SecondOrderLengthTable full, middle, back;
};

// Throws vri::Error as build_second_order_length_table, with 3 lengths * N^3
// entries counted against kMaxSecondOrderEntries.
SecondOrderWeightedLengthTables build_second_order_weighted_length_tables(const SecondOrderBuilder& builder,
                                                                          const DiscreteTf& tf, int lengths,
                                                                          double max_length, int iterations);

}  // namespace vri
