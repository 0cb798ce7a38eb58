#pragma once
// gzip (and zlib) streams through zlib, for NRRD's gzip encoding.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace vri {

// Inflates a gzip or zlib stream straight into `out` (a volume's storage),
// dropping its first `skip` bytes; returns the bytes written. Throws
// vri::Error on corrupt data or if the stream holds more than skip + out.size().
// Concatenated gzip members are read as one stream.
std::size_t gunzip_into(std::span<const std::byte> in, std::size_t skip, std::span<std::byte> out);

// The same stream handed to `sink` a window at a time, (offset after the
// skip, bytes): a reader keeps what it needs (one brick of a volume) and
// never holds the whole. Throws as gunzip_into past `limit` bytes.
std::uint64_t gunzip_each(std::span<const std::byte> in, std::uint64_t skip, std::uint64_t limit,
                          const std::function<void(std::uint64_t, std::span<const std::byte>)>& sink);

// Deflates into a gzip stream.
std::vector<std::byte> gzip(std::span<const std::byte> in);

}  // namespace vri
