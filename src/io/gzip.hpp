#pragma once
// gzip (and zlib) streams through zlib, for NRRD's gzip encoding.
#include <cstddef>
#include <span>
#include <vector>

namespace vri {

// Inflates a gzip or zlib stream; throws vri::Error on corrupt data or if the
// output would exceed max_bytes.
std::vector<std::byte> gunzip(std::span<const std::byte> in, std::size_t max_bytes);

// Deflates into a gzip stream.
std::vector<std::byte> gzip(std::span<const std::byte> in);

}  // namespace vri
