#include "vri/core/zeroed_floats.hpp"

#include <sys/mman.h>

#include <cstring>
#include <string>
#include <utility>

#include "vri/core/error.hpp"

namespace vri {

ZeroedFloats::ZeroedFloats(std::size_t count) : size_(count) {
  if (count == 0) return;
  void* p = mmap(nullptr, count * sizeof(float), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw Error("out of memory for " + std::to_string(count * sizeof(float)) + " bytes");
  madvise(p, count * sizeof(float), MADV_HUGEPAGE);  // advice only: 4 KiB pages work too
  data_ = static_cast<float*>(p);
}

ZeroedFloats::ZeroedFloats(const ZeroedFloats& other) : ZeroedFloats(other.size_) {
  if (size_) std::memcpy(data_, other.data_, size_ * sizeof(float));
}

ZeroedFloats::ZeroedFloats(ZeroedFloats&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)) {}

ZeroedFloats& ZeroedFloats::operator=(ZeroedFloats other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  return *this;
}

ZeroedFloats::~ZeroedFloats() {
  if (data_) munmap(data_, size_ * sizeof(float));
}

}  // namespace vri
