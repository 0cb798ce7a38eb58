#pragma once
// Whole-file reads, and writes that never leave a partial file behind.
#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace vri {

// Reads the whole file; throws vri::Error naming the path if it cannot.
std::vector<std::byte> read_file(const std::filesystem::path& path);

// Writes to a temporary file beside `path`, then renames it into place, so a
// failure never leaves a truncated output. Throws vri::Error on failure.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::byte> bytes);

}  // namespace vri
