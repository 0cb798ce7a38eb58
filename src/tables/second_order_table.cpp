#include "tables/second_order_table.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "tables/second_order_chords.hpp"
#include "tables/trilinear.hpp"
#include "vri/error.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/second_order_exact.hpp"
#include "tables/second_order_fast.hpp"
#include "tables/second_order_plain.hpp"
#include "tables/slab_integral.hpp"

namespace vri {

namespace {

std::size_t cube(std::size_t n) { return n * n * n; }

std::size_t checked_entries(int n) {
  if (cube(n) > kMaxSecondOrderEntries)
    throw Error("a second-order table of size " + std::to_string(n) + " exceeds " +
                std::to_string(kMaxSecondOrderEntries) + " entries (1 GiB); use --size <= 406");
  return cube(n);
}

}  // namespace

SecondOrderTable::SecondOrderTable(const ScalarAxis& axis, double length, int iterations)
    : axis_(axis), length_(length), iterations_(iterations), data_(4 * checked_entries(axis.n)) {}

Rgba SecondOrderTable::lookup(double s_f, double s_m, double s_b) const {
  return trilinear_rgba(data(), axis_.n, axis_.index(s_f), axis_.index(s_m), axis_.index(s_b));
}

SlabRgba second_order_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b, double length,
                            int iterations) {
  SlabRgba acc;
  detail::for_each_second_order_chord(tf, u_f, u_m, u_b, length, iterations,
                                      [&](double, double, double u0, double u1, double step) {
                                        acc = over(acc, exact_index_slab(tf, u0, u1, step));
                                      });
  return acc;
}

void write_straight_entries(const DiscreteTf& tf, SecondOrderTable& table) {
  // Lum et al.'s incremental table of the whole length: every slab (f, b) to
  // 1e-9 in O(N^2) and the pieces once (an exact slab each took seconds
  // under 500 control points, 32 lengths of preint2-dual).
  const PreintegrationTable slabs = IncrementalBuilder().build(tf, table.length());
  const int n = tf.size();
  for (int f = 0; f < n; ++f)
    for (int b = f % 2; b < n; b += 2)  // f + b even: m = (f + b) / 2 is an entry
      std::copy_n(slabs.entry(f, b), 4, table.entry(f, (f + b) / 2, b));
}

void check_iterations(int iterations) {
  if (iterations < 1 || iterations > kMaxSecondOrderIterations)
    throw Error("--iterations must be in [1, " + std::to_string(kMaxSecondOrderIterations) + "], got " +
                std::to_string(iterations));
}

std::unique_ptr<SecondOrderBuilder> make_second_order_builder(const std::string& name) {
  if (name == "plain") return std::make_unique<PlainSecondOrderBuilder>();
  if (name == "fast") return std::make_unique<FastSecondOrderBuilder>();
  if (name == "exact") return std::make_unique<ExactSecondOrderBuilder>();
  throw Error("unknown second-order table builder '" + name + "' (known: plain, fast, exact)");
}

SecondOrderLengthTable::SecondOrderLengthTable(std::vector<SecondOrderTable> slices, double max_length)
    : slices_(std::move(slices)), max_length_(max_length) {
  if (slices_.size() < 2) throw Error("a table with lengths needs at least 2 lengths");
}

Rgba SecondOrderLengthTable::lookup(double length, double s_f, double s_m, double s_b) const {
  const LengthBracket l = length_bracket(length, max_length_, static_cast<int>(slices_.size()));
  const Rgba lo = slices_[l.i].lookup(s_f, s_m, s_b), hi = slices_[l.i + 1].lookup(s_f, s_m, s_b);
  Rgba out;
  for (int c = 0; c < 4; ++c) out[c] = (1 - l.w) * lo[c] + l.w * hi[c];
  return out;
}

std::size_t SecondOrderLengthTable::bytes() const {
  std::size_t total = 0;
  for (const auto& s : slices_) total += s.bytes();
  return total;
}

void check_length_table(int lengths, double max_length, int n, int tables) {
  if (lengths < 2) throw Error("--lengths must be >= 2, got " + std::to_string(lengths));
  if (!(max_length > 0) || !std::isfinite(max_length))
    throw Error("--max-length must be a positive number, got " + format_g(max_length));
  if (static_cast<std::size_t>(tables) * lengths * cube(n) > kMaxSecondOrderEntries)
    throw Error("a second-order table of " + (tables > 1 ? std::to_string(tables) + " x " : std::string()) +
                std::to_string(lengths) + " lengths x " + std::to_string(n) + "^3 entries exceeds " +
                std::to_string(kMaxSecondOrderEntries) + " entries (1 GiB)");
}

SecondOrderLengthTable build_second_order_length_table(const SecondOrderBuilder& builder, const DiscreteTf& tf,
                                                       int lengths, double max_length, int iterations) {
  check_length_table(lengths, max_length, tf.size(), 1);
  check_iterations(iterations);
  std::vector<SecondOrderTable> slices;
  // Length 0 is the empty slab; builders take only positive lengths. The
  // builders are parallel inside, so the lengths go one after the other.
  slices.emplace_back(tf.axis(), 0.0, iterations);
  for (int m = 1; m < lengths; ++m) slices.push_back(builder.build(tf, max_length * m / (lengths - 1), iterations));
  return SecondOrderLengthTable(std::move(slices), max_length);
}

}  // namespace vri
