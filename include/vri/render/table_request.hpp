#pragma once
// TableRequest: one pre-integration table as `vri table` (SPEC §10) and the
// Python vri.table ask for it, built by one function so both give the same
// bytes and the same refusals.
//   order 1, one length:   shape (N, N, 4)     indexed [s_f, s_b]
//   order 1, M lengths:    shape (M, N, N, 4)  indexed [l, s_f, s_b], l = LMAX m / (M - 1)
//   order 2:               shape (N, N, N, 4)  indexed [s_f, s_m, s_b] (El Hajjar et al. 2008)
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vri/transfer/transfer_function.hpp"

namespace vri {

struct TableRequest {
  int size = 256, order = 1;
  double length = 1;                  // slab length, world units
  std::optional<int> lengths;         // order 1: M lengths (with max_length)
  std::optional<double> max_length;
  std::optional<std::string> builder; // order 1: brute, incremental (default), sliced, engel, exact; order 2: plain, fast (default), exact
  std::optional<int> iterations;      // order 2: chords per slab (default kDefaultSecondOrderIterations)
  int steps = 0;                      // sliced: integration steps (0: 2N)
  std::string accumulation = "fp32";  // sliced: 8bit, 12bit, fp16, fp32
  // cpu or vulkan (order 1: sliced, the default there, fp32 only; order 2:
  // fast): where the table is built (vri/render/backend.hpp).
  std::string backend = "cpu";
};

struct BuiltTable {
  std::vector<std::size_t> shape;
  std::span<const float> data;  // float32 premultiplied RGBA, C order
  std::shared_ptr<const void> owner;  // the table the data lives in (no copy)
  std::string builder;      // the builder's own name, with " (vulkan)" when built there
  double seconds = 0;       // build time (the table alone)
};

// Throws vri::Error for a bad order, size, builder or a flag of the other order.
BuiltTable build_table(const TransferFunction& tf, const TableRequest& request);

}  // namespace vri
