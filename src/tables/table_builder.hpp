#pragma once
// TableBuilder: one way of computing a PreintegrationTable. Every builder
// computes the same entries (slab_integral.hpp), exactly or approximately;
// `exact` is the reference the others are tested against. Builders run on
// oneTBB and give the same bytes for any thread count.
#include <tbb/parallel_for.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "tables/discrete_tf.hpp"
#include "tables/preintegration_table.hpp"

namespace vri {

class TableBuilder {
 public:
  virtual ~TableBuilder() = default;
  virtual std::string_view name() const = 0;
  // The (N, N) table for slabs of `length` world units (> 0).
  virtual PreintegrationTable build(const DiscreteTf& tf, double length) const = 0;
  // About how many integrand evaluations one build of an N-entry table
  // takes, in the units of --max-work (one ray sample is one): the mesh
  // methods build one table per length and check the sum before building.
  virtual double work(int n) const = 0;
  // The same for the lengths - 1 non-empty slices of a length table
  // (build_length_table): work(n) each, unless a builder's work grows with
  // the slabs' optical depth, as brute's quadrature panels do.
  virtual double length_table_work(const DiscreteTf& tf, int lengths, double max_length) const {
    (void)max_length;
    return work(tf.size()) * (lengths - 1);
  }
};

// Throws vri::Error unless length is finite and > 0; every build() calls it.
void check_slab_length(double length);

// The (M, N, N) table: one build per length max_length * m / (M - 1), the
// lengths built concurrently. Throws vri::Error unless M >= 2, max_length > 0
// and the table fits in kMaxLengthTableEntries.
inline constexpr std::size_t kMaxLengthTableEntries = std::size_t{1} << 26;  // 1 GiB of RGBA floats
LengthTable build_length_table(const TableBuilder& builder, const DiscreteTf& tf, int lengths,
                               double max_length);

// build_length_table's refusals for `tables` tables of M x N x N entries together.
void check_length_tables(int lengths, double max_length, int n, int tables);

// The M slices of a length table, slices[m] = build(max_length * m / (M - 1))
// for m >= 1 and empty(0) for the empty slab (builders take only positive
// lengths), built concurrently; each slice's bytes depend on its length only.
template <class Slice, class Build, class Empty>
std::vector<Slice> build_length_slices(int lengths, double max_length, Build build, Empty empty) {
  std::vector<std::optional<Slice>> built(lengths);
  tbb::parallel_for(0, lengths, [&](int m) {
    if (m == 0) built[m].emplace(empty());
    else built[m].emplace(build(max_length * m / (lengths - 1)));
  });
  std::vector<Slice> slices;
  for (auto& t : built) slices.push_back(std::move(*t));
  return slices;
}

// "brute", "incremental", "sliced" (its defaults), "engel", "exact"; throws vri::Error naming the known ones otherwise.
std::unique_ptr<TableBuilder> make_table_builder(const std::string& name);
// Inline: the scene loader checks names with it without linking the builders
// (the fuzz build compiles the parsers alone).
inline const std::vector<std::string>& known_builder_names() {
  static const std::vector<std::string> names = {"brute", "incremental", "sliced", "engel", "exact"};
  return names;
}

}  // namespace vri
