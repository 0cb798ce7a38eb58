#pragma once
// Sizes declared by files (dims, counts, byte lengths) multiplied in 64-bit
// arithmetic with overflow detection, so a hostile header cannot wrap a check.
#include <cstdint>
#include <initializer_list>
#include <string>

namespace vri {

// The product of `factors`; throws vri::Error "<what> is too large" when it
// does not fit in 64 bits.
std::uint64_t checked_product(std::initializer_list<std::uint64_t> factors, const std::string& what);

// a + b, or throws vri::Error "<what> is too large" on overflow.
std::uint64_t checked_sum(std::uint64_t a, std::uint64_t b, const std::string& what);

}  // namespace vri
