#pragma once
// Whole-file and ranged reads, and writes that never leave a partial file behind.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <span>
#include <string>
#include <vector>

#include "vri/core/charged_vector.hpp"

namespace vri {

// Reads the whole file; throws vri::Error naming the path if it cannot.
ChargedVector<std::byte> read_file(const std::filesystem::path& path);
// The same as text (a scene, a transfer function, a colour map).
std::string text_of(const std::filesystem::path& path);
// vri::FileError unless `path` is missing (the open says so) or a regular
// file: a FIFO would block the open forever, a device never ends (issue 47).
// Every reader of vri calls it before opening.
void require_regular_file(const std::filesystem::path& path);

// The file's size in bytes; throws vri::Error naming the path if it has none.
std::uint64_t checked_file_size(const std::filesystem::path& path);

// Reads out.size() bytes from `offset` on straight into `out` (a volume's own
// storage: no file-sized copy beside it); throws vri::Error if it cannot.
void read_file_range(const std::filesystem::path& path, std::uint64_t offset, std::span<std::byte> out);
// The same from a stream already open on `path` (a reader of many ranges
// opens the file once); errors name `path`.
void read_stream_range(std::istream& in, const std::filesystem::path& path, std::uint64_t offset,
                       std::span<std::byte> out);

// Writes to a temporary file created exclusively beside `path`, then renames
// it into place, so a failure never leaves a truncated output. Inside an
// OutputTransaction the rename waits for its commit(). Throws vri::Error.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::byte> bytes);
// The same for a file made of `parts`, one after another.
void write_file_atomically(const std::filesystem::path& path, std::span<const std::span<const std::byte>> parts);

}  // namespace vri
