#pragma once
// BruteBuilder: every entry integrated on its own, piece by piece
// (slab_integral.hpp, control points inside a bin included), each piece's
// colour integral int c tau T dt evaluated directly by 8-point Gauss-Legendre
// on panels of optical depth <= 1/2 with T in closed form - a different formula from linear_piece, so
// the builders check each other (`exact`, exact_builder.hpp, is the
// reference). O(N^3) for N x N (Lum, Wilson & Ma 2004, §4.1).
#include "tables/slab_rgba.hpp"
#include "tables/table_builder.hpp"

namespace vri {

class BruteBuilder final : public TableBuilder {
 public:
  std::string_view name() const override { return "brute"; }
  // n^2 entries of (n + 2) / 3 bins on average, 8 Gauss-Legendre points a bin.
  double work(int n) const override { return 8.0 * n * n * (n + 2) / 3; }
  // Counts the panels too: a piece of optical depth d takes up to
  // min(4 d + 1, 201) of them (quadrature_piece), so one tetrahedron at
  // coordinates 3e38 costs 200 times an ordinary one (issue 47, item 8).
  double length_table_work(const DiscreteTf& tf, int lengths, double max_length) const override;
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;
};

// The forward piece of linear_piece, by direct quadrature (exposed for tests).
SlabRgba quadrature_piece(const TfSample& p, const TfSample& q, double d);

}  // namespace vri
