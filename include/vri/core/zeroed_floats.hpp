#pragma once
// ZeroedFloats: a large float array that starts at zero, taken straight from
// the kernel (anonymous mmap, zero by definition) and backed by 2 MiB pages
// where the kernel allows (madvise). Why: a 256 MiB second-order table
// filled through std::vector spent half its build time in memset and 4 KiB
// page faults; this way the builders' own writes fault 2 MiB at a time, in
// parallel. From 1 MiB up the mapping is whole, aligned 2 MiB pages (a
// first-order table of N = 256 is 1 MiB); below, calloc (a fresh mapping's
// 4 KiB page faults cost more than clearing reused heap memory). Copies copy
// the contents. Images are held the same way (render/image.hpp): a 512 x 512
// RGBA image (4 MiB) took 11.8 ms to zero on 4 KiB pages on the project VM,
// a quarter of a preint1 frame, and 0.3-0.8 ms on 2 MiB pages.
#include <cstddef>
#include <string_view>

#include "vri/core/memory_limit.hpp"

namespace vri {

class ZeroedFloats {
 public:
  ZeroedFloats() = default;
  // Throws vri::Error when over the memory budget (naming `what`) or out of memory.
  explicit ZeroedFloats(std::size_t count, std::string_view what = "a table");
  ZeroedFloats(const ZeroedFloats& other);
  ZeroedFloats(ZeroedFloats&& other) noexcept;
  ZeroedFloats& operator=(ZeroedFloats other) noexcept;
  ~ZeroedFloats();

  float* data() { return data_; }
  const float* data() const { return data_; }
  std::size_t size() const { return size_; }
  float& operator[](std::size_t i) { return data_[i]; }
  const float& operator[](std::size_t i) const { return data_[i]; }

 private:
  float* data_ = nullptr;
  std::size_t size_ = 0;
  MemoryCharge charge_;  // the process's account holds these bytes while they live
};

}  // namespace vri
