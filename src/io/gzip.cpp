#include "gzip.hpp"

#include <zlib.h>

#include <algorithm>
#include <string>

#include "vri/error.hpp"

namespace vri {

std::uint64_t gunzip_each(std::span<const std::byte> in, std::uint64_t skip, std::uint64_t limit,
                          const std::function<void(std::uint64_t, std::span<const std::byte>)>& sink) {
  z_stream zs{};
  if (inflateInit2(&zs, 15 + 32) != Z_OK) throw Error("zlib: cannot initialise inflate");
  const auto fail = [&](const std::string& what) {
    inflateEnd(&zs);
    throw Error(what);
  };
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<std::byte*>(in.data()));
  zs.avail_in = static_cast<uInt>(in.size());
  // Inflated a window at a time: the skipped bytes dropped, the rest handed
  // on; one byte past `limit` is the error.
  std::vector<std::byte> window(1 << 16);
  std::uint64_t delivered = 0;
  int rc = Z_OK;
  while (rc != Z_STREAM_END) {
    zs.next_out = reinterpret_cast<Bytef*>(window.data());
    zs.avail_out = static_cast<uInt>(window.size());
    rc = inflate(&zs, Z_NO_FLUSH);
    if (rc != Z_OK && rc != Z_STREAM_END)
      fail(std::string("gzip data is corrupt or truncated") + (zs.msg ? std::string(" (") + zs.msg + ")" : ""));
    std::span<const std::byte> got(window.data(), window.size() - zs.avail_out);
    const std::uint64_t dropped = std::min<std::uint64_t>(skip, got.size());
    skip -= dropped;
    got = got.subspan(dropped);
    if (got.size() > limit - delivered)
      fail("gzip data expands beyond the expected " + std::to_string(limit) + " bytes");
    if (!got.empty()) {
      try {
        sink(delivered, got);
      } catch (...) {
        inflateEnd(&zs);
        throw;
      }
      delivered += got.size();
    }
    if (rc == Z_OK && zs.avail_in == 0 && zs.avail_out == window.size()) fail("gzip data is truncated");
    // Concatenated gzip members (`cat a.gz b.gz`, pigz, bgzip) form one
    // stream, as gzip -d reads them; bytes after the last member are ignored.
    if (rc == Z_STREAM_END && zs.avail_in >= 2 && zs.next_in[0] == 0x1f && zs.next_in[1] == 0x8b) {
      if (inflateReset(&zs) != Z_OK) fail("zlib: cannot reset inflate");
      rc = Z_OK;
    }
  }
  inflateEnd(&zs);
  return delivered;
}

std::size_t gunzip_into(std::span<const std::byte> in, std::size_t skip, std::span<std::byte> out) {
  return gunzip_each(in, skip, out.size(), [&](std::uint64_t offset, std::span<const std::byte> bytes) {
    std::copy(bytes.begin(), bytes.end(), out.begin() + static_cast<std::ptrdiff_t>(offset));
  });
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
