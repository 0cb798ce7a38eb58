#include "vri/memory.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

#include "vri/error.hpp"

namespace vri {

namespace {

constexpr std::size_t kPage = std::size_t(2) << 20;  // one transparent huge page

// From 1 MiB up, whole 2 MiB pages, so that every byte sits on a huge page (a
// 1 MiB table, N = 256, then faults once instead of 256 times, at the price of
// at most doubling its footprint). Below, calloc: the heap's memory is
// reused, and clearing it costs less than a fresh mapping's 4 KiB page
// faults, which are dear on a VM (N = 128: 0.85 ms mapped, PERFORMANCE.md).
bool mapped(std::size_t count) { return count * sizeof(float) >= kPage / 2; }

std::size_t mapped_bytes(std::size_t count) { return (count * sizeof(float) + kPage - 1) / kPage * kPage; }

}  // namespace

ZeroedFloats::ZeroedFloats(std::size_t count, std::string_view what) : size_(count) {
  if (count == 0) return;
  charge_ = MemoryCharge(count, sizeof(float), std::string(what) + " of " + std::to_string(count) + " floats");
  if (!mapped(count)) {
    data_ = static_cast<float*>(std::calloc(count, sizeof(float)));
    if (!data_) throw Error("out of memory for " + std::to_string(count * sizeof(float)) + " bytes");
    return;
  }
  const std::size_t bytes = mapped_bytes(count);
  // Huge pages need a 2 MiB-aligned address: map a page more, unmap the ends.
  void* p = mmap(nullptr, bytes + kPage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw Error("out of memory for " + std::to_string(count * sizeof(float)) + " bytes");
  char* const start = static_cast<char*>(p);
  char* const aligned = start + (kPage - reinterpret_cast<std::uintptr_t>(start) % kPage) % kPage;
  if (aligned > start) munmap(start, aligned - start);
  munmap(aligned + bytes, start + kPage - aligned);  // never empty: aligned - start < kPage
  madvise(aligned, bytes, MADV_HUGEPAGE);  // advice only: 4 KiB pages work too
  data_ = reinterpret_cast<float*>(aligned);
}

ZeroedFloats::ZeroedFloats(const ZeroedFloats& other) : ZeroedFloats(other.size_) {
  if (size_) std::memcpy(data_, other.data_, size_ * sizeof(float));
}

ZeroedFloats::ZeroedFloats(ZeroedFloats&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)), size_(std::exchange(other.size_, 0)),
      charge_(std::move(other.charge_)) {}

ZeroedFloats& ZeroedFloats::operator=(ZeroedFloats other) noexcept {
  std::swap(data_, other.data_);
  std::swap(size_, other.size_);
  charge_.swap(other.charge_);
  return *this;
}

ZeroedFloats::~ZeroedFloats() {
  if (!data_) return;
  if (mapped(size_)) munmap(data_, mapped_bytes(size_));
  else std::free(data_);
}

}  // namespace vri
