#pragma once
// vri/memory.hpp: the process's memory budget (--max-memory), the charges held against it and the containers that charge it.

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <cstddef>
#include <memory>
#include <vector>
#include <string_view>

// ---- memory_limit ----------------------------------------------------------
// A process-wide memory budget consulted before big allocations (volume
// samples, mesh arrays, gradient fields, tables, images), so a size declared
// by a file or asked for on the command line fails with a clear message
// instead of exhausting the machine. Default: 75% of physical memory;
// `--max-memory`. It is one account for the whole process: what is held by a
// MemoryCharge (volume samples, gradient fields, tables, images, meshes, the
// GPU's rays) counts against every later check, so two structures that each
// fit cannot together pass it.
// An AccountScope adds a second, smaller account on one thread (the viewer's
// per-client budget, docs/RELIABILITY.md).

namespace vri {

// The current budget in bytes.
std::uint64_t memory_limit();
// Sets the budget (0 restores the default).
void set_memory_limit(std::uint64_t bytes);
// 75% of physical memory (sysconf), or 4 GiB where it cannot be read.
std::uint64_t default_memory_limit();

// Throws vri::Error naming `what` and the bytes it would take when `bytes`,
// added to what is held now, exceeds the budget (or the thread's account's,
// see AccountScope), and saying how to raise it.
void check_allocation(std::uint64_t bytes, const std::string& what);
// check_allocation for count * size bytes, with overflow detection.
void check_allocation(std::uint64_t count, std::uint64_t size, const std::string& what);

// Bytes held now by MemoryCharges in the whole process.
std::uint64_t memory_in_use();

// A second budget, for the charges made on the threads that enter it with an
// AccountScope (one viewer client's). Must outlive every charge made to it.
class MemoryAccount {
 public:
  MemoryAccount(std::string name, std::uint64_t limit) : name_(std::move(name)), limit_(limit) {}
  MemoryAccount(const MemoryAccount&) = delete;
  MemoryAccount& operator=(const MemoryAccount&) = delete;
  const std::string& name() const { return name_; }
  std::uint64_t limit() const { return limit_; }
  std::uint64_t in_use() const { return used_.load(std::memory_order_relaxed); }

 private:
  friend class MemoryCharge;
  std::string name_;
  std::uint64_t limit_;
  std::atomic<std::uint64_t> used_{0};
};

// While it lives, MemoryCharges made on this thread also count against
// `account` (nested scopes: the innermost).
class AccountScope {
 public:
  explicit AccountScope(MemoryAccount& account);
  ~AccountScope();
  AccountScope(const AccountScope&) = delete;
  AccountScope& operator=(const AccountScope&) = delete;

 private:
  MemoryAccount* previous_;
};

// Bytes held against the process's budget (and the thread's account) from
// construction to destruction: the structure that owns it is counted for as
// long as it lives. Throws vri::Error, as check_allocation, when they do not fit.
class MemoryCharge {
 public:
  MemoryCharge() = default;
  MemoryCharge(std::uint64_t bytes, const std::string& what);
  MemoryCharge(std::uint64_t count, std::uint64_t size, const std::string& what);
  // A charge to the process's budget only, not to the thread's account: for
  // data that may outlive the scope (a volume the viewer's catalog shares
  // between pages; an account must outlive its charges).
  static MemoryCharge process_only(std::uint64_t bytes, const std::string& what);
  // A copy of a structure charges its bytes again.
  MemoryCharge(const MemoryCharge& other) : MemoryCharge(other.bytes_, "a copy") {}
  MemoryCharge& operator=(const MemoryCharge& other) {
    MemoryCharge(other).swap(*this);
    return *this;
  }
  MemoryCharge(MemoryCharge&& other) noexcept { swap(other); }
  MemoryCharge& operator=(MemoryCharge&& other) noexcept {
    MemoryCharge(std::move(other)).swap(*this);
    return *this;
  }
  ~MemoryCharge();
  void swap(MemoryCharge& other) noexcept {
    std::swap(bytes_, other.bytes_);
    std::swap(account_, other.account_);
  }
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::uint64_t bytes_ = 0;
  MemoryAccount* account_ = nullptr;
};

// For ChargedAllocator (vri/memory.hpp): adds `bytes` to the
// process's account, throwing as MemoryCharge does when they do not fit; and
// gives them back.
void charge_process_bytes(std::uint64_t bytes, const std::string& what);
void release_process_bytes(std::uint64_t bytes) noexcept;

// Parses "1073741824", "512M", "4G", "1.5G", "64K", "2T" (powers of 1024);
// nullopt on anything else or zero.
std::optional<std::uint64_t> parse_byte_size(const std::string& text);

// "4.1 GB"-style text for messages (powers of 1024: KiB, MiB, GiB).
std::string format_bytes(std::uint64_t bytes);

}  // namespace vri

// ---- charged_vector --------------------------------------------------------
// ChargedVector<T>: a std::vector whose storage is charged to the process's
// memory budget (vri/memory.hpp) while it is held - for the
// temporary arrays a reader builds while it parses a file (the file's bytes,
// its values as doubles, its indices) and a renderer's working arrays (the
// projected tetrahedra's tile lists and fragments), which together can pass
// the budget though each was checked alone (issue 47).

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

// ---- zeroed_floats ---------------------------------------------------------
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
