#include "core/checked_size.hpp"

#include "vri/error.hpp"

namespace vri {

std::uint64_t checked_product(std::initializer_list<std::uint64_t> factors, const std::string& what) {
  std::uint64_t p = 1;
  for (std::uint64_t f : factors)
    if (__builtin_mul_overflow(p, f, &p)) throw Error(what + " is too large (overflows 64 bits)");
  return p;
}

std::uint64_t checked_sum(std::uint64_t a, std::uint64_t b, const std::string& what) {
  std::uint64_t s;
  if (__builtin_add_overflow(a, b, &s)) throw Error(what + " is too large (overflows 64 bits)");
  return s;
}

}  // namespace vri
