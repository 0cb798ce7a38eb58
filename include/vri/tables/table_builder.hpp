#pragma once
// TableBuilder: one way of computing a PreintegrationTable. Every builder
// computes the same entries (slab_integral.hpp), exactly or approximately;
// `brute` is the reference the others are tested against. Builders run on
// oneTBB and give the same bytes for any thread count.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/preintegration_table.hpp"

namespace vri {

class TableBuilder {
 public:
  virtual ~TableBuilder() = default;
  virtual std::string_view name() const = 0;
  // The (N, N) table for slabs of `length` world units (> 0).
  virtual PreintegrationTable build(const DiscreteTf& tf, double length) const = 0;
};

// Throws vri::Error unless length is finite and > 0; every build() calls it.
void check_slab_length(double length);

// The (M, N, N) table: one build per length max_length * m / (M - 1), the
// lengths built concurrently. Throws vri::Error unless M >= 2, max_length > 0
// and the table fits in kMaxLengthTableEntries.
inline constexpr std::size_t kMaxLengthTableEntries = std::size_t{1} << 26;  // 1 GiB of RGBA floats
LengthTable build_length_table(const TableBuilder& builder, const DiscreteTf& tf, int lengths,
                               double max_length);

// "brute", "incremental", "sliced" (its defaults), "engel"; throws vri::Error naming the known ones otherwise.
std::unique_ptr<TableBuilder> make_table_builder(const std::string& name);
const std::vector<std::string>& known_builder_names();

}  // namespace vri
