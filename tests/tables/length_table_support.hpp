#pragma once
// The (l, s_f, s_b) table of the mesh tests, built by the reference builder
// (`brute`) so that table error, not builder error, is what those tests see.
#include <memory>

#include "tables/brute_builder.hpp"
#include "tables/table_builder.hpp"

namespace vri::test {

inline LengthTable length_table(const TransferFunction& tf, int size, int lengths, double max_length) {
  return build_length_table(BruteBuilder(), DiscreteTf(tf, size), lengths, max_length);
}

inline std::unique_ptr<LengthTable> length_table_ptr(const TransferFunction& tf, int size, int lengths,
                                                     double max_length) {
  return std::make_unique<LengthTable>(length_table(tf, size, lengths, max_length));
}

}  // namespace vri::test
