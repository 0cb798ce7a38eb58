#include "tables/table_builder.hpp"

#include <cmath>
#include <string>

#include "vri/error.hpp"
#include "tables/brute_builder.hpp"
#include "tables/engel_builder.hpp"
#include "tables/exact_builder.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/sliced_builder.hpp"

namespace vri {

LengthTable build_length_table(const TableBuilder& builder, const DiscreteTf& tf, int lengths,
                               double max_length) {
  check_length_tables(lengths, max_length, tf.size(), 1);
  return LengthTable(build_length_slices<PreintegrationTable>(
                         lengths, max_length, [&](double l) { return builder.build(tf, l); },
                         [&] { return PreintegrationTable(tf.axis(), 0); }),
                     max_length);
}

void check_length_tables(int lengths, double max_length, int n, int tables) {
  if (lengths < 2) throw Error("--lengths must be >= 2, got " + std::to_string(lengths));
  if (!(max_length > 0) || !std::isfinite(max_length))
    throw Error("--max-length must be a positive number, got " + format_g(max_length));
  if (static_cast<std::size_t>(tables) * lengths * n * n > kMaxLengthTableEntries)
    throw Error("a table of " + (tables > 1 ? std::to_string(tables) + " x " : std::string()) +
                std::to_string(lengths) + " x " + std::to_string(n) + " x " + std::to_string(n) +
                " entries is too large");
}

std::unique_ptr<TableBuilder> make_table_builder(const std::string& name) {
  if (name == "brute") return std::make_unique<BruteBuilder>();
  if (name == "incremental") return std::make_unique<IncrementalBuilder>();
  if (name == "sliced") return std::make_unique<SlicedBuilder>();
  if (name == "engel") return std::make_unique<EngelBuilder>();
  if (name == "exact") return std::make_unique<ExactBuilder>();
  std::string list;
  for (const auto& n : known_builder_names()) list += (list.empty() ? "" : ", ") + n;
  throw Error("unknown table builder '" + name + "' (known: " + list + ")");
}

void check_slab_length(double length) {
  if (!(length > 0) || !std::isfinite(length))
    throw Error("slab length must be a positive number, got " + format_g(length));
}

}  // namespace vri
