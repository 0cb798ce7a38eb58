#include "vri/memory.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "vri/error.hpp"

namespace vri {

namespace {
std::atomic<std::uint64_t> g_limit{0};  // 0: the default
std::atomic<std::uint64_t> g_in_use{0};
thread_local MemoryAccount* t_account = nullptr;

std::string over_limit(std::uint64_t bytes, const std::string& what, std::uint64_t limit, std::uint64_t held,
                       const std::string& whose) {
  std::string m = what + " would need " + format_bytes(bytes) + " (" + std::to_string(bytes) + " bytes), over " +
                  whose + " of " + format_bytes(limit);
  if (held) m += " with " + format_bytes(held) + " already held";
  return m;
}

// Whether `bytes` more fit under `limit` with `held` held (no overflow).
bool fits(std::uint64_t bytes, std::uint64_t held, std::uint64_t limit) { return bytes <= limit - std::min(held, limit); }

[[noreturn]] void refuse_process(std::uint64_t bytes, const std::string& what, std::uint64_t held) {
  throw Error(over_limit(bytes, what, memory_limit(), held, "the memory limit") +
              "; raise it with --max-memory (e.g. --max-memory 64G)");
}

[[noreturn]] void refuse_account(std::uint64_t bytes, const std::string& what, const MemoryAccount& a,
                                 std::uint64_t held) {
  throw Error(over_limit(bytes, what, a.limit(), held, a.name()));
}

// Adds `bytes` to `used` if they fit under `limit`, in one step (compare-
// exchange), so two threads cannot both pass a check only one of them fits;
// else false, with `held` what was there.
bool add_if_fits(std::atomic<std::uint64_t>& used, std::uint64_t bytes, std::uint64_t limit, std::uint64_t& held) {
  held = used.load(std::memory_order_relaxed);
  do {
    if (!fits(bytes, held, limit)) return false;
  } while (!used.compare_exchange_weak(held, held + bytes, std::memory_order_relaxed));
  return true;
}

std::uint64_t product(std::uint64_t count, std::uint64_t size, const std::string& what) {
  std::uint64_t bytes;
  if (__builtin_mul_overflow(count, size, &bytes))
    throw Error(what + " would need more than 2^64 bytes (" + std::to_string(count) + " x " +
                std::to_string(size) + ")");
  return bytes;
}
}  // namespace

std::uint64_t default_memory_limit() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::uint64_t{4} << 30;
  return std::uint64_t(pages) / 4 * 3 * std::uint64_t(page);
}

std::uint64_t memory_limit() {
  const std::uint64_t l = g_limit.load(std::memory_order_relaxed);
  return l ? l : default_memory_limit();
}

void set_memory_limit(std::uint64_t bytes) { g_limit.store(bytes, std::memory_order_relaxed); }

std::string format_bytes(std::uint64_t bytes) {
  static const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = double(bytes);
  int u = 0;
  while (v >= 1024 && u < 6) v /= 1024, ++u;
  char buf[48];
  if (u == 0) std::snprintf(buf, sizeof buf, "%llu bytes", static_cast<unsigned long long>(bytes));
  else std::snprintf(buf, sizeof buf, "%.3g %s", v, units[u]);
  return buf;
}

std::uint64_t memory_in_use() { return g_in_use.load(std::memory_order_relaxed); }

void check_allocation(std::uint64_t bytes, const std::string& what) {
  const std::uint64_t held = memory_in_use();
  if (!fits(bytes, held, memory_limit())) refuse_process(bytes, what, held);
  if (const MemoryAccount* a = t_account; a && !fits(bytes, a->in_use(), a->limit()))
    refuse_account(bytes, what, *a, a->in_use());
}

AccountScope::AccountScope(MemoryAccount& account) : previous_(std::exchange(t_account, &account)) {}
AccountScope::~AccountScope() { t_account = previous_; }

void charge_process_bytes(std::uint64_t bytes, const std::string& what) {
  std::uint64_t held;
  if (!add_if_fits(g_in_use, bytes, memory_limit(), held)) refuse_process(bytes, what, held);
}

void release_process_bytes(std::uint64_t bytes) noexcept { g_in_use.fetch_sub(bytes, std::memory_order_relaxed); }

MemoryCharge::MemoryCharge(std::uint64_t bytes, const std::string& what) {
  if (bytes == 0) return;
  charge_process_bytes(bytes, what);
  if (MemoryAccount* a = t_account) {
    std::uint64_t held;
    if (!add_if_fits(a->used_, bytes, a->limit(), held)) {
      release_process_bytes(bytes);
      refuse_account(bytes, what, *a, held);
    }
    account_ = a;
  }
  bytes_ = bytes;
}

MemoryCharge::MemoryCharge(std::uint64_t count, std::uint64_t size, const std::string& what)
    : MemoryCharge(product(count, size, what), what) {}

MemoryCharge MemoryCharge::process_only(std::uint64_t bytes, const std::string& what) {
  struct Outside {  // the thread's account, put back however the charge ends
    MemoryAccount* saved = std::exchange(t_account, nullptr);
    ~Outside() { t_account = saved; }
  } outside;
  return MemoryCharge(bytes, what);
}

MemoryCharge::~MemoryCharge() {
  if (!bytes_) return;
  release_process_bytes(bytes_);
  if (account_) account_->used_.fetch_sub(bytes_, std::memory_order_relaxed);
}

void check_allocation(std::uint64_t count, std::uint64_t size, const std::string& what) {
  check_allocation(product(count, size, what), what);
}

std::optional<std::uint64_t> parse_byte_size(const std::string& text) {
  if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text[0])) || text[0] == '.')) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  std::string suffix(end);
  if (!suffix.empty() && (suffix.back() == 'B' || suffix.back() == 'b')) suffix.pop_back();
  if (suffix.size() == 2 && (suffix[1] == 'i' || suffix[1] == 'I')) suffix.pop_back();  // GiB
  double scale = 1;
  if (suffix.size() > 1) return std::nullopt;
  if (suffix.size() == 1) {
    switch (suffix[0]) {
      case 'k': case 'K': scale = 1024.0; break;
      case 'm': case 'M': scale = 1024.0 * 1024; break;
      case 'g': case 'G': scale = 1024.0 * 1024 * 1024; break;
      case 't': case 'T': scale = 1024.0 * 1024 * 1024 * 1024; break;
      default: return std::nullopt;
    }
  }
  const double bytes = std::floor(v * scale);
  if (!(bytes >= 1) || !(bytes < 1.8e19)) return std::nullopt;
  return static_cast<std::uint64_t>(bytes);
}

}  // namespace vri
