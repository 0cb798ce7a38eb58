#pragma once
// HalfSecondOrderTable: a SecondOrderTable stored as 16-bit half floats
// (IEEE binary16: 11 significant bits), 8 bytes per entry instead
// of 16: 128 MiB for 256^3 (float32: 256 MiB). Every stored value is the
// nearest half to the float32 one, so |half - float| <= 2^-11 |x| + 2^-25
// (2.4e-4 at most for values in [0, 1]; the measured max and RMS over a
// 256^3 table are in docs/SECOND_ORDER.md). Lookups are trilinear like
// SecondOrderTable::lookup.
#include <cstddef>
#include <vector>

#include "vri/memory.hpp"
#include "vri/geometry.hpp"
#include "tables/second_order_table.hpp"

namespace vri {

class HalfSecondOrderTable {
 public:
  // IEEE binary16 storage: _Float16 (GCC 12 has it in C++ on x86-64), Arm's
  // __fp16 on Arm (there GCC 12 has _Float16 in C alone); both round to nearest.
#if defined(__aarch64__) || defined(__arm__)
  using Half = __fp16;
#else
  using Half = _Float16;
#endif

  explicit HalfSecondOrderTable(const SecondOrderTable& table);

  const ScalarAxis& axis() const { return axis_; }
  int size() const { return axis_.n; }
  double length() const { return length_; }
  int iterations() const { return iterations_; }
  // Entry (f, m, b) widened to double.
  Rgba entry(int f, int m, int b) const;
  std::size_t bytes() const { return data_.size() * sizeof(Half); }

  Rgba lookup(double s_f, double s_m, double s_b) const;

 private:
  ScalarAxis axis_;
  double length_;
  int iterations_;
  MemoryCharge charge_;  // data_'s bytes, held before it is allocated
  std::vector<Half> data_;
};

}  // namespace vri
