#include "tables/half_second_order_table.hpp"

#include <tbb/parallel_for.h>

#include "tables/trilinear.hpp"

namespace vri {

HalfSecondOrderTable::HalfSecondOrderTable(const SecondOrderTable& table)
    : axis_(table.axis()),
      length_(table.length()),
      iterations_(table.iterations()),
      charge_(table.bytes() / sizeof(float), sizeof(Half), "the half-precision copy of a second-order table"),
      data_(table.bytes() / sizeof(float)) {
  const float* src = table.data();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, data_.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) data_[i] = static_cast<Half>(src[i]);
  });
}

Rgba HalfSecondOrderTable::entry(int f, int m, int b) const {
  const std::size_t n = axis_.n, k = 4 * ((static_cast<std::size_t>(f) * n + m) * n + b);
  return {double(data_[k]), double(data_[k + 1]), double(data_[k + 2]), double(data_[k + 3])};
}

Rgba HalfSecondOrderTable::lookup(double s_f, double s_m, double s_b) const {
  return trilinear_rgba(data_.data(), axis_.n, axis_.index(s_f), axis_.index(s_m), axis_.index(s_b));
}

}  // namespace vri
