#pragma once
// Weighted pre-integration tables for interpolated lighting (Lum, Wilson &
// Ma 2004, §3, §4.3, §5.1). Across a slab from s_f to s_b the back weight u
// runs from 0 at the front sample to 1 at the back one, the front weight is
// 1 - u, and
//   diffuse:  D_w = int w(u) c tau T dt   (the transfer function's colour)
//   specular: S_w = int w(u) tau T dt     (white),
// so D_front + D_back = C and S_front + S_back = alpha of the unweighted
// slab. As in the paper (§4.3, where each table sample x gets the weight
// W(x) = (x - i) / (j - i)), the weight is applied to the colour at the table
// scalars and the weighted colour is linear between them, like the colour
// itself (SPEC §10); for the white specular this is the exact u.
//
// Packing (§5.1): two RGBA tables,
//   front = (D_front.rgb, alpha),   back = (D_back.rgb, S_back),
// and S_front = alpha - S_back.
#include "tables/discrete_tf.hpp"
#include "tables/preintegration_table.hpp"
#include "tables/slab_integral.hpp"
#include "tables/slab_rgba.hpp"

namespace vri {

struct WeightedTables {
  PreintegrationTable front, back;  // packed as above
};

// One slab's weighted integrals, unpacked: rgb = D_w, a = S_w.
struct SlabWeights {
  SlabRgba front, back;
};

// The paper's O(N^2) build (§4.3): the unweighted table C_1 and the globally
// ramped tables C_G (colours, and white, multiplied by the table index k),
// all composited over the incremental builder's diagonals, then
//   C_W(i, j) = (C_G(i, j) - i C_1(i, j)) / (j - i)   (i != j, both sides of
// the diagonal), in double before rounding to float, so the cancellation in
// C_G - i C_1 costs ~1e-13, not float's 1e-7 N; the diagonal (a homogeneous
// slab, optical depth A = tau l) in closed form:
//   D_back = c beta(A), S_back = beta(A), beta(A) = int_0^1 u A e^{-A u} du = (1 - e^{-A}(1 + A)) / A.
// Throws vri::Error for a bad length.
WeightedTables build_weighted_tables(const DiscreteTf& tf, double length);

// The reference: every entry integrated on its own, front and back weights
// separately, with BruteBuilder's quadrature. O(N^3).
WeightedTables brute_weighted_tables(const DiscreteTf& tf, double length);

// The slab from continuous index u_f to u_b of length l with both weights,
// each integral composited piece by piece with piece(front, back, d) -> SlabRgba
// (integrate_slab): the weights are those at the piece ends, t / l being the
// back weight at distance t.
template <class PieceFn>
SlabWeights weighted_slab(const DiscreteTf& tf, double u_f, double u_b, double length, PieceFn piece) {
  const auto one = [&](bool toward_back, bool white) {
    const auto weigh = [&](TfSample v, double t) {
      const double w = toward_back ? t / length : 1 - t / length;
      if (white) v.r = v.g = v.b = 1;
      v.r *= w, v.g *= w, v.b *= w;
      return v;
    };
    if (u_f == u_b) {  // homogeneous: the weight alone is linear across the slab
      const TfSample v = tf.at_index(u_f);
      return piece(weigh(v, 0), weigh(v, length), length);
    }
    double t = 0;
    return integrate_slab(tf, u_f, u_b, length, [&](const TfSample& p, const TfSample& q, double d) {
      const double t0 = t;
      t += d;
      return piece(weigh(p, t0), weigh(q, t), d);
    });
  };
  const SlabRgba df = one(false, false), db = one(true, false);
  return {{df.r, df.g, df.b, one(false, true).r}, {db.r, db.g, db.b, one(true, true).r}};
}

// weighted_slab with linear_piece at any scalars, packed as the tables: what
// a table lookup at (s_f, s_b) approximates, for the partial last slab.
SlabWeights exact_weighted_slab(const DiscreteTf& tf, double s_f, double s_b, double length);

// The weighted (l, s_f, s_b) tables of the mesh methods' interpolated
// lighting (chord_lighting.hpp): slice m of each is the packed table above
// for length max_length * m / (M - 1) (build_weighted_tables per slice, the
// slices built concurrently; slice 0, the empty slab, is 0), lookups linear in
// l like any LengthTable. front + back = the unweighted LengthTable.
// Memory: 2 M N^2 x 16 bytes, 32 MiB at N = 128, M = 64 (twice the unweighted table).
struct WeightedLengthTables {
  LengthTable front, back;
};

// Throws vri::Error as build_length_table, both tables counted against kMaxLengthTableEntries.
WeightedLengthTables build_weighted_length_tables(const DiscreteTf& tf, int lengths, double max_length);

// The packing of §5.1 from unpacked weights.
inline SlabWeights pack(const SlabWeights& w) {
  return {{w.front.r, w.front.g, w.front.b, w.front.a + w.back.a}, w.back};
}

}  // namespace vri
