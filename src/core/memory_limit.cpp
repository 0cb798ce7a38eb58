#include "vri/core/memory_limit.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

#include "vri/core/error.hpp"

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
  const std::uint64_t limit = memory_limit(), held = memory_in_use();
  if (bytes > limit || bytes > limit - std::min(held, limit))
    throw Error(over_limit(bytes, what, limit, held, "the memory limit") +
                "; raise it with --max-memory (e.g. --max-memory 64G)");
  if (const MemoryAccount* a = t_account) {
    const std::uint64_t mine = a->in_use();
    if (bytes > a->limit() || bytes > a->limit() - std::min(mine, a->limit()))
      throw Error(over_limit(bytes, what, a->limit(), mine, a->name()));
  }
}

AccountScope::AccountScope(MemoryAccount& account) : previous_(std::exchange(t_account, &account)) {}
AccountScope::~AccountScope() { t_account = previous_; }

// Check and add in one step per account (compare-exchange), so two threads
// charging at once cannot both pass a check that only one of them fits.
MemoryCharge::MemoryCharge(std::uint64_t bytes, const std::string& what) {
  if (bytes == 0) return;
  const std::uint64_t limit = memory_limit();
  std::uint64_t held = g_in_use.load(std::memory_order_relaxed);
  do {
    if (bytes > limit || bytes > limit - std::min(held, limit))
      throw Error(over_limit(bytes, what, limit, held, "the memory limit") +
                  "; raise it with --max-memory (e.g. --max-memory 64G)");
  } while (!g_in_use.compare_exchange_weak(held, held + bytes, std::memory_order_relaxed));
  if (MemoryAccount* a = t_account) {
    std::uint64_t mine = a->used_.load(std::memory_order_relaxed);
    do {
      if (bytes > a->limit() || bytes > a->limit() - std::min(mine, a->limit())) {
        g_in_use.fetch_sub(bytes, std::memory_order_relaxed);
        throw Error(over_limit(bytes, what, a->limit(), mine, a->name()));
      }
    } while (!a->used_.compare_exchange_weak(mine, mine + bytes, std::memory_order_relaxed));
    account_ = a;
  }
  bytes_ = bytes;
}

MemoryCharge::MemoryCharge(std::uint64_t count, std::uint64_t size, const std::string& what) {
  std::uint64_t bytes;
  if (__builtin_mul_overflow(count, size, &bytes))
    throw Error(what + " would need more than 2^64 bytes (" + std::to_string(count) + " x " +
                std::to_string(size) + ")");
  MemoryCharge(bytes, what).swap(*this);
}

MemoryCharge::~MemoryCharge() {
  if (!bytes_) return;
  g_in_use.fetch_sub(bytes_, std::memory_order_relaxed);
  if (account_) account_->used_.fetch_sub(bytes_, std::memory_order_relaxed);
}

void check_allocation(std::uint64_t count, std::uint64_t size, const std::string& what) {
  std::uint64_t bytes;
  if (__builtin_mul_overflow(count, size, &bytes))
    throw Error(what + " would need more than 2^64 bytes (" + std::to_string(count) + " x " +
                std::to_string(size) + ")");
  check_allocation(bytes, what);
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
