#pragma once
// Pieces the regular-grid readers share (NRRD, MetaImage, .npy): the sample
// types files hold beyond vri's ScalarType (bool, 64-bit integers, half
// floats), decoded into a GridVolume's storage under the memory budget;
// mirroring the samples along axes (a file whose axis runs backwards); and
// the folder rule for a header's detached data file (docs/RELIABILITY.md).
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>

#include "vri/error.hpp"
#include "vri/volume.hpp"

namespace vri {

// A file's sample type. Those ScalarType has go through GridVolume::decode
// (uint8, uint16, int16 and float32 kept in their own type); Bool is kept as
// uint8 holding 0 or 1; Int64, UInt64 and Float16 become float.
enum class FileSampleType { Bool, Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float16, Float32, Float64 };

std::size_t file_sample_size(FileSampleType type);

// `count` samples of `type`, decoded as GridVolume::decode does: `fill`
// writes exactly count * file_sample_size(type) bytes into the span it is
// given. The memory budget is checked before anything is allocated.
GridVolume::Samples decode_file_samples(FileSampleType type, Endian endian, std::uint64_t count,
                                        const std::function<void(std::span<std::byte>)>& fill);

// Mirrors x-fastest samples of `dims` along each axis whose `flip` is set,
// in place (a file storing an axis from its high end to its low end).
void flip_samples(GridVolume::Samples& samples, std::array<int, 3> dims, std::array<bool, 3> flip);

// Header text: `s` without leading and trailing blanks (space, tab, CR); `s`
// in lower case.
std::string trim_blanks(const std::string& s);
std::string to_lower(std::string s);

// fn(), with a vri::Error it throws prefixed by `where` ("NRRD 'a.nrrd': ...")
// so that the one line names the file; a FileError already names its own.
template <class F>
auto naming_file(const std::string& where, F&& fn) {
  try {
    return fn();
  } catch (const FileError&) {
    throw;
  } catch (const Error& e) {
    throw Error(where + ": " + e.what());
  }
}

// Copies out.size() bytes at `offset` of `bytes` (a file given in memory);
// vri::Error if they run past its end.
void copy_range(std::span<const std::byte> bytes, std::uint64_t offset, std::span<std::byte> out);

// The data file `name` a header in `header_dir` points to. Unless
// `allow_outside`, absolute paths and paths leaving that folder (.., symlinks
// out) are refused: a header from a stranger must not read arbitrary files.
// `where` starts the error ("NRRD 'a.nhdr'"), `key` names the header field.
std::filesystem::path detached_data_path(const std::filesystem::path& header_dir, const std::string& name,
                                         bool allow_outside, const std::string& where, const std::string& key);

}  // namespace vri
