#pragma once
// Second-order pre-integration (El Hajjar, Marchesin, Dischler & Mongenet
// 2008, "Second order pre-integrated volume rendering", PacificVis): the
// scalar along a slab of length L is the parabola through its front, middle
// and back samples (their Eq. 2, which defines the entry),
//
//   P(t) = A t^2 + B t + C,  A = 2 s_f - 4 s_m + 2 s_b,  B = -3 s_f + 4 s_m - s_b,
//   C = s_f,  t in [0, 1],
//
// and the table over (s_f, s_m, s_b) holds the slab integral of SPEC §4 along
// it. As in the paper (§6.2: a fixed number of iterations, Horner) the slab is
// walked in K = `iterations` equal steps of length L/K, but each step is a
// chord: from P(t_k) to P(t_{k+1}), t_j = j/K (each clamped to the axis, SPEC
// §3), the scalar linear along it, integrated exactly like a first-order slab
// (slab_integral.hpp) through every control point it crosses - inside a table
// bin too, so a spike narrower than a bin is never stepped over (issue 16) -
// and the chords composited front to back. Chords depart from the parabola by
// |A|/(8K^2) in the scalar, so entries converge as O(1/K^2).
// Entries are float32 premultiplied RGBA, indexed [s_f][s_m][s_b].
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/memory.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/slab_rgba.hpp"
#include "tables/slab_table.hpp"  // length_bracket

namespace vri {

// The most entries (all lengths together) a second-order table may have:
// 2^26 entries = 1 GiB of float32 RGBA (a 256^3 table is 2^24 = 256 MiB; one
// length needs N <= 406).
inline constexpr std::size_t kMaxSecondOrderEntries = std::size_t{1} << 26;
inline constexpr int kMaxSecondOrderIterations = 4096;
// The default K: 8 chords are as accurate as 64 on the bundled scenes (the
// chords integrate what they cross; docs/SECOND_ORDER.md) at an eighth of the work.

class SecondOrderTable {
 public:
  // All-zero entries (length 0 is the empty slab). Throws vri::Error when
  // axis.n^3 exceeds kMaxSecondOrderEntries.
  SecondOrderTable(const ScalarAxis& axis, double length, int iterations);

  const ScalarAxis& axis() const { return axis_; }
  int size() const { return axis_.n; }
  double length() const { return length_; }
  int iterations() const { return iterations_; }
  // Entry (f, m, b): 4 floats r, g, b, alpha.
  float* entry(int f, int m, int b) { return &data_[offset(f, m, b)]; }
  const float* entry(int f, int m, int b) const { return &data_[offset(f, m, b)]; }
  const float* data() const { return data_.data(); }
  std::size_t bytes() const { return data_.size() * sizeof(float); }

  // Trilinear in the continuous indices of s_f, s_m, s_b.
  Rgba lookup(double s_f, double s_m, double s_b) const;

 private:
  std::size_t offset(int f, int m, int b) const {
    const std::size_t n = axis_.n;
    return 4 * ((static_cast<std::size_t>(f) * n + m) * n + b);
  }
  ScalarAxis axis_;
  double length_;
  int iterations_;
  ZeroedFloats data_;
};

// One entry of the model above at continuous indices (DiscreteTf::at_index)
// u_f, u_m, u_b, in double precision: the definition every builder is held to.
SlabRgba second_order_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b, double length,
                            int iterations);

// Throws vri::Error unless 1 <= iterations <= kMaxSecondOrderIterations.
void check_iterations(int iterations);

// Where the parabola through (f, m, b) is straight (2 m = f + b) the entry is
// the first-order slab from f to b. Builders whose chords are lookups (fast,
// on the CPU and the GPU) were up to 0.38 from it at steps and spikes
// narrower than a bin, the more the more chords (issue 46): they overwrite
// these N^2 / 2 entries with the slab itself, from the incremental table of
// the whole length (to 1e-9; the chords of `plain` compose to it).
void write_straight_entries(const DiscreteTf& tf, SecondOrderTable& table);

struct SecondOrderWeightedTables;  // second_order_weighted.hpp

class SecondOrderBuilder {
 public:
  virtual ~SecondOrderBuilder() = default;
  virtual std::string_view name() const = 0;
  // The (N, N, N) table of slabs of `length` (> 0) with K = `iterations` chords.
  virtual SecondOrderTable build(const DiscreteTf& tf, double length, int iterations) const = 0;
  // The same table and the two weighted ones of second_order_weighted.hpp
  // (interpolated lighting), in one pass; `full` has build()'s bytes.
  virtual SecondOrderWeightedTables build_weighted(const DiscreteTf& tf, double length, int iterations) const = 0;
};

// "plain", "fast" or "exact"; throws vri::Error naming the known ones otherwise.
std::unique_ptr<SecondOrderBuilder> make_second_order_builder(const std::string& name);

// The (s_f, s_m, s_b, l) table of preint2-dual: M slices at lengths
// max_length * m / (M - 1), linear in l (clamped to [0, max_length]).
class SecondOrderLengthTable {
 public:
  // slices[m] must have length max_length * m / (M - 1); M >= 2.
  SecondOrderLengthTable(std::vector<SecondOrderTable> slices, double max_length);

  const std::vector<SecondOrderTable>& slices() const { return slices_; }
  double max_length() const { return max_length_; }
  Rgba lookup(double length, double s_f, double s_m, double s_b) const;
  std::size_t bytes() const;

 private:
  std::vector<SecondOrderTable> slices_;
  double max_length_;
};

// Throws vri::Error unless lengths >= 2, max_length > 0 and
// tables * lengths * n^3 <= kMaxSecondOrderEntries (1 GiB).
void check_length_table(int lengths, double max_length, int n, int tables);

// Throws vri::Error unless lengths >= 2, max_length > 0 and lengths * N^3 <=
// kMaxSecondOrderEntries (1 GiB).
SecondOrderLengthTable build_second_order_length_table(const SecondOrderBuilder& builder, const DiscreteTf& tf,
                                                       int lengths, double max_length, int iterations);

}  // namespace vri
