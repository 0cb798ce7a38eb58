#pragma once
// A process-wide memory budget consulted before big allocations (volume
// samples, mesh arrays, gradient fields, tables), so a size declared by a file
// or asked for on the command line fails with a clear message instead of
// exhausting the machine. Default: 75% of physical memory; `--max-memory`.
#include <cstdint>
#include <optional>
#include <string>

namespace vri {

// The current budget in bytes.
std::uint64_t memory_limit();
// Sets the budget (0 restores the default).
void set_memory_limit(std::uint64_t bytes);
// 75% of physical memory (sysconf), or 4 GiB where it cannot be read.
std::uint64_t default_memory_limit();

// Throws vri::Error naming `what` and the bytes it would take when `bytes`
// exceeds the budget, and saying how to raise it.
void check_allocation(std::uint64_t bytes, const std::string& what);
// check_allocation for count * size bytes, with overflow detection.
void check_allocation(std::uint64_t count, std::uint64_t size, const std::string& what);

// Parses "1073741824", "512M", "4G", "1.5G", "64K", "2T" (powers of 1024);
// nullopt on anything else or zero.
std::optional<std::uint64_t> parse_byte_size(const std::string& text);

// "4.1 GB"-style text for messages (powers of 1024: KiB, MiB, GiB).
std::string format_bytes(std::uint64_t bytes);

}  // namespace vri
