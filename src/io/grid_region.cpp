#include "io/grid_region.hpp"

#include <algorithm>
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "vri/error.hpp"
#include "vri/io.hpp"

namespace vri {

namespace {

// The byte offset of row (j, k) of the region in the whole layout, and the
// offset of that row in the region's storage.
struct Rows {
  std::array<int, 3> dims;
  GridRegion region;
  std::size_t size;  // bytes a sample
  std::uint64_t in_file(int j, int k) const {
    return ((std::uint64_t(k) * dims[1] + j) * dims[0] + region.lo[0]) * size;
  }
  std::uint64_t in_region(int j, int k) const {
    const auto d = region.dims();
    return (std::uint64_t(k - region.lo[2]) * d[1] + (j - region.lo[1])) * d[0] * size;
  }
  std::uint64_t row_bytes() const { return std::uint64_t(region.dims()[0]) * size; }
};

}  // namespace

GridVolume::Samples read_region(ScalarType type, Endian endian, std::array<int, 3> dims, const GridRegion& region,
                                const std::function<void(std::uint64_t, std::span<std::byte>)>& read) {
  check_region(region, dims);
  const Rows rows{dims, region, scalar_type_size(type)};
  return GridVolume::decode(type, endian, region.points(), [&](std::span<std::byte> out) {
    // The region's rows are packed in `out`; a run grows while the next row
    // follows the last in the file too.
    std::uint64_t run_file = 0, run_out = 0, run_bytes = 0;
    for (int k = region.lo[2]; k <= region.hi[2]; ++k)
      for (int j = region.lo[1]; j <= region.hi[1]; ++j) {
        const std::uint64_t file = rows.in_file(j, k);
        if (run_bytes && file == run_file + run_bytes) {
          run_bytes += rows.row_bytes();
          continue;
        }
        if (run_bytes) read(run_file, out.subspan(run_out, run_bytes));
        run_file = file, run_out = rows.in_region(j, k), run_bytes = rows.row_bytes();
      }
    if (run_bytes) read(run_file, out.subspan(run_out, run_bytes));
  });
}

GridVolume::Samples read_region_from_file(const std::filesystem::path& path, std::uint64_t start, ScalarType type,
                                          Endian endian, std::array<int, 3> dims, const GridRegion& region) {
  require_regular_file(path);
  struct Fd {
    int fd;
    ~Fd() {
      if (fd >= 0) ::close(fd);
    }
  } file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) throw FileError("cannot open '" + path.string() + "': " + std::strerror(errno));
  return read_region(type, endian, dims, region, [&](std::uint64_t offset, std::span<std::byte> out) {
    std::size_t done = 0;
    while (done < out.size()) {
      const ssize_t n = ::pread(file.fd, out.data() + done, out.size() - done, off_t(start + offset + done));
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw FileError("cannot read " + std::to_string(out.size()) + " bytes at " + std::to_string(start + offset) +
                        " of '" + path.string() + "'" + (n < 0 ? std::string(": ") + std::strerror(errno) : ""));
      done += std::size_t(n);
    }
  });
}

GridVolume::Samples read_region_streamed(
    ScalarType type, Endian endian, std::array<int, 3> dims, const GridRegion& region,
    const std::function<void(const std::function<void(std::uint64_t, std::span<const std::byte>)>&)>& feed) {
  check_region(region, dims);
  const Rows rows{dims, region, scalar_type_size(type)};
  return GridVolume::decode(type, endian, region.points(), [&](std::span<std::byte> out) {
    // The rows in stream order; each piece fills the parts of the rows it overlaps.
    int j = region.lo[1], k = region.lo[2];
    feed([&](std::uint64_t offset, std::span<const std::byte> piece) {
      const std::uint64_t piece_end = offset + piece.size();
      while (k <= region.hi[2]) {
        const std::uint64_t row = rows.in_file(j, k), row_end = row + rows.row_bytes();
        if (row >= piece_end) return;  // this row starts in a later piece
        const std::uint64_t from = std::max(row, offset), to = std::min(row_end, piece_end);
        if (from < to)
          std::copy(piece.begin() + static_cast<std::ptrdiff_t>(from - offset),
                    piece.begin() + static_cast<std::ptrdiff_t>(to - offset),
                    out.begin() + static_cast<std::ptrdiff_t>(rows.in_region(j, k) + (from - row)));
        if (row_end > piece_end) return;  // the row goes on in the next piece
        if (++j > region.hi[1]) j = region.lo[1], ++k;
      }
    });
    if (k <= region.hi[2]) throw Error("the data ends before the region does");
  });
}

}  // namespace vri
