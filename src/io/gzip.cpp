#include "gzip.hpp"

#include <zlib.h>

#include <algorithm>
#include <string>

#include "vri/core/error.hpp"

namespace vri {

std::size_t gunzip_into(std::span<const std::byte> in, std::size_t skip, std::span<std::byte> out) {
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 32) != Z_OK) throw Error("zlib: cannot initialise inflate");
  const auto fail = [&](const std::string& what) {
    inflateEnd(&zs);
    throw Error(what);
  };
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(in.data()));
  zs.avail_in = static_cast<uInt>(in.size());
  // The skipped bytes go through a small buffer, the rest into `out`, a
  // window of at most 1 GiB at a time (avail_out is 32-bit); one spare byte
  // past the end catches a stream that holds more than it should.
  std::byte spare[1 << 16];
  std::size_t written = 0;
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    Bytef* window;
    std::size_t room;
    if (skip > 0) {
      window = reinterpret_cast<Bytef*>(spare), room = std::min(skip, sizeof spare);
    } else if (written < out.size()) {
      window = reinterpret_cast<Bytef*>(out.data() + written), room = std::min<std::size_t>(out.size() - written, 1 << 30);
    } else {
      window = reinterpret_cast<Bytef*>(spare), room = 1;
    }
    zs.next_out = window;
    zs.avail_out = static_cast<uInt>(room);
    rc = inflate(&zs, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END)
      fail(std::string("gzip data is corrupt or truncated") + (zs.msg ? std::string(" (") + zs.msg + ")" : ""));
    const std::size_t got = room - zs.avail_out;
    if (skip > 0) {
      skip -= got;
    } else if (written < out.size()) {
      written += got;
    } else if (got > 0) {
      fail("gzip data expands beyond the expected " + std::to_string(out.size()) + " bytes");
    }
    if (rc == Z_OK && zs.avail_in == 0 && got == 0) fail("gzip data is truncated");
    // Concatenated gzip members (`cat a.gz b.gz`, pigz, bgzip) form one
    // stream, as gzip -d reads them; bytes after the last member are ignored.
    if (rc == Z_STREAM_END && zs.avail_in >= 2 && zs.next_in[0] == 0x1f && zs.next_in[1] == 0x8b) {
      if (inflateReset(&zs) != Z_OK) fail("zlib: cannot reset inflate");
      rc = Z_OK;
    }
  }
  inflateEnd(&zs);
  return written;
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
