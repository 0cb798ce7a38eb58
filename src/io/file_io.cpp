#include "vri/io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <system_error>
#include <unistd.h>

#include "vri/error.hpp"

namespace vri {

namespace fs = std::filesystem;

std::string text_of(const std::filesystem::path& path) {
  const auto bytes = read_file(path);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

void require_regular_file(const fs::path& path) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec) return;  // missing or unreachable: the open says why
  if (fs::is_directory(st)) throw FileError("cannot read '" + path.string() + "': is a directory");
  if (!fs::is_regular_file(st))
    throw FileError("cannot read '" + path.string() + "': not a regular file (a FIFO, device or socket)");
}

ChargedVector<std::byte> read_file(const fs::path& path) {
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw FileError("cannot open '" + path.string() + "': " + std::strerror(errno));
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw FileError("cannot read '" + path.string() + "'");
  in.seekg(0);
  check_allocation(std::uint64_t(size), "the file '" + path.string() + "'");
  ChargedVector<std::byte> bytes(static_cast<std::size_t>(size));
  if (size > 0 && !in.read(reinterpret_cast<char*>(bytes.data()), size))
    throw FileError("cannot read '" + path.string() + "'");
  return bytes;
}

std::uint64_t checked_file_size(const fs::path& path) {
  require_regular_file(path);
  std::error_code ec;
  const auto size = fs::file_size(path, ec);
  if (ec) throw FileError("cannot open '" + path.string() + "': " + ec.message());
  return size;
}

void read_file_range(const fs::path& path, std::uint64_t offset, std::span<std::byte> out) {
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("cannot open '" + path.string() + "': " + std::strerror(errno));
  read_stream_range(in, path, offset, out);
}

void read_stream_range(std::istream& in, const fs::path& path, std::uint64_t offset, std::span<std::byte> out) {
  in.seekg(static_cast<std::streamoff>(offset));
  if (!in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(out.size())))
    throw FileError("cannot read " + std::to_string(out.size()) + " bytes at " + std::to_string(offset) + " of '" +
                path.string() + "'");
}

void write_file_atomically(const fs::path& path, std::span<const std::byte> bytes) {
  write_file_atomically(path, std::span(&bytes, 1));
}

void write_file_atomically(const fs::path& path, std::span<const std::span<const std::byte>> parts) {
  if (OutputTransaction* active = OutputTransaction::active()) return active->stage(path, parts);
  OutputTransaction own;
  own.stage(path, parts);
  own.commit();
}

}  // namespace vri
