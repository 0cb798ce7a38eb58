#pragma once
// ChargedVector<T>: a std::vector whose storage is charged to the process's
// memory budget (vri/core/memory_limit.hpp) while it is held - for the
// temporary arrays a reader builds while it parses a file (the file's bytes,
// its values as doubles, its indices) and a renderer's working arrays (the
// projected tetrahedra's tile lists and fragments), which together can pass
// the budget though each was checked alone (issue 47).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "vri/core/memory_limit.hpp"

namespace vri {

template <class T>
struct ChargedAllocator {
  using value_type = T;
  ChargedAllocator() = default;
  template <class U>
  ChargedAllocator(const ChargedAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::uint64_t bytes = bytes_of(n);
    charge_process_bytes(bytes, "a working array of " + std::to_string(n) + " values");
    try {
      return std::allocator<T>().allocate(n);
    } catch (...) {
      release_process_bytes(bytes);
      throw;
    }
  }
  void deallocate(T* p, std::size_t n) noexcept {
    std::allocator<T>().deallocate(p, n);
    release_process_bytes(bytes_of(n));
  }
  friend bool operator==(const ChargedAllocator&, const ChargedAllocator&) { return true; }

 private:
  static std::uint64_t bytes_of(std::size_t n) {
    std::uint64_t bytes;
    if (__builtin_mul_overflow(std::uint64_t(n), std::uint64_t(sizeof(T)), &bytes)) throw std::bad_array_new_length();
    return bytes;
  }
};

template <class T>
using ChargedVector = std::vector<T, ChargedAllocator<T>>;

}  // namespace vri
