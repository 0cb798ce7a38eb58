#include "gzip.hpp"

#include <zlib.h>

#include <string>

#include "vri/core/error.hpp"

namespace vri {

std::vector<std::byte> gunzip(std::span<const std::byte> in, std::size_t max_bytes) {
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 32) != Z_OK) throw Error("zlib: cannot initialise inflate");
  std::vector<std::byte> out;
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(in.data()));
  zs.avail_in = static_cast<uInt>(in.size());
  int rc = Z_OK;
  std::byte chunk[1 << 16];
  while (rc != Z_STREAM_END) {
    zs.next_out = reinterpret_cast<Bytef*>(chunk);
    zs.avail_out = sizeof(chunk);
    rc = inflate(&zs, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END) {
      inflateEnd(&zs);
      throw Error(std::string("gzip data is corrupt or truncated") +
                  (zs.msg ? std::string(" (") + zs.msg + ")" : ""));
    }
    const std::size_t got = sizeof(chunk) - zs.avail_out;
    if (out.size() + got > max_bytes) {
      inflateEnd(&zs);
      throw Error("gzip data expands beyond the expected " + std::to_string(max_bytes) +
                  " bytes");
    }
    out.insert(out.end(), chunk, chunk + got);
    if (rc == Z_OK && zs.avail_in == 0 && got == 0) {
      inflateEnd(&zs);
      throw Error("gzip data is truncated");
    }
  }
  inflateEnd(&zs);
  return out;
}

std::vector<std::byte> gzip(std::span<const std::byte> in) {
  z_stream zs{};
  if (deflateInit2(&zs, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw Error("zlib: cannot initialise deflate");
  std::vector<std::byte> out(deflateBound(&zs, static_cast<uLong>(in.size())) + 64);
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(in.data()));
  zs.avail_in = static_cast<uInt>(in.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&zs, Z_FINISH);
  deflateEnd(&zs);
  if (rc != Z_STREAM_END) throw Error("zlib: deflate failed");
  out.resize(zs.total_out);
  return out;
}

}  // namespace vri
