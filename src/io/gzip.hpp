#pragma once
// gzip (and zlib) streams through zlib, for NRRD's gzip encoding.
#include <cstddef>
#include <span>
#include <vector>

namespace vri {

// Inflates a gzip or zlib stream straight into `out` (a volume's storage),
// dropping its first `skip` bytes; returns the bytes written. Throws
// vri::Error on corrupt data or if the stream holds more than skip + out.size().
// Concatenated gzip members are read as one stream.
std::size_t gunzip_into(std::span<const std::byte> in, std::size_t skip, std::span<std::byte> out);

// Deflates into a gzip stream.
std::vector<std::byte> gzip(std::span<const std::byte> in);

}  // namespace vri
