#pragma once
// vri/io.hpp: files in and out: reading any volume file, .npy, PNG, raw volumes, and outputs written all or nothing.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <span>
#include <string>
#include <vector>
#include <string_view>
#include <array>

#include "vri/memory.hpp"
#include "vri/image.hpp"
#include "vri/volume.hpp"
#include "vri/geometry.hpp"

// ---- file_io ---------------------------------------------------------------
// Whole-file and ranged reads, and writes that never leave a partial file behind.

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

// ---- output_transaction ----------------------------------------------------
// All the files one command writes, committed together (issue 17): each
// output is written to a temporary created exclusively (O_CREAT|O_EXCL|
// O_NOFOLLOW) beside its target, and only commit() renames them into place.
// Destruction without commit, SIGINT and SIGTERM remove the temporaries, so a
// failed or interrupted command leaves no output at all.

namespace vri {

class OutputTransaction {
 public:
  // Becomes the active transaction: write_file_atomically() stages into it.
  OutputTransaction();
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;

  // Writes `bytes` to a fresh temporary beside `target`; throws vri::Error.
  void stage(const std::filesystem::path& target, std::span<const std::byte> bytes);
  // The same for a file made of `parts`, one after another (a header and an
  // image's pixels, without a copy of them side by side).
  void stage(const std::filesystem::path& target, std::span<const std::span<const std::byte>> parts);
  // Renames every staged temporary onto its target; throws vri::Error (and
  // removes the temporaries not yet renamed) if one cannot be.
  void commit();
  // Creates the folder `dir` (and its missing parents) for outputs staged in
  // it; without a commit they are removed again, once empty (a turntable
  // that failed left an empty frames folder, issue 47).
  void create_directories(const std::filesystem::path& dir);

  // The active transaction of this process, or nullptr.
  static OutputTransaction* active();

 private:
  struct Staged {
    std::filesystem::path temp, target;
  };
  std::vector<Staged> staged_;
  std::vector<std::filesystem::path> created_;  // folders made here, deepest first
  OutputTransaction* previous_;
  void discard() noexcept;
};

// Installs SIGINT/SIGTERM handlers that unlink every temporary still staged,
// then re-raise the signal with its default action; ignores SIGXFSZ, so a
// write past the file-size limit fails (EFBIG) and the transaction cleans up
// instead of the process dying with its temporaries left.
void remove_temporaries_on_signal();

}  // namespace vri

// ---- volume_file -----------------------------------------------------------
// Volume files of every format vri reads (issue 20, item 1; docs/FORMATS.md),
// told apart by their magic bytes first and their extension second, so a
// file is read by what it is, not by what it is called.

namespace vri {

enum class VolumeFormat {
  Raw,                  // headerless samples: the scene gives dims and type (SPEC §1)
  Nrrd,                 // .nrrd, .nhdr
  VolvisDat,            // .dat: three uint16 dims, then uint16 samples
  Vti,                  // VTK XML image data
  VtkStructuredPoints,  // legacy VTK, DATASET STRUCTURED_POINTS
  MetaImage,            // ITK's .mhd / .mha
  Npy,                  // NumPy, indexed [z, y, x]
  Tiff,                 // a multi-page TIFF (page = z, row = y), or a folder of one-page slices
  VtkLegacyMesh,        // legacy VTK, DATASET UNSTRUCTURED_GRID (a tetrahedral mesh)
  Vtu,                  // VTK XML unstructured grid (a tetrahedral mesh)
};

// The format of the first bytes `head` (up to 1 KiB) of a file called `name`:
// the magic bytes decide ("II*\0", "MM\0*" and BigTIFF's "II+\0", "MM\0+"
// are TIFF); without them .dat is volvis and anything else raw.
// vri::Error for a VTK XML file of another data set type.
VolumeFormat volume_format(std::span<const std::byte> head, const std::filesystem::path& name);
// The same for a file on disk (its first KiB); a folder is a folder of TIFF
// slices (io/tiff.hpp). vri::FileError if it cannot be read.
VolumeFormat volume_format(const std::filesystem::path& path);

bool is_mesh(VolumeFormat format);
std::string_view format_name(VolumeFormat format);
// For error messages: every format with its extensions.
std::string_view supported_formats();

}  // namespace vri

// ---- npy -------------------------------------------------------------------
// NumPy .npy files of float32 (written) and float32/float64 (read), C order;
// and volumes from .npy (NumPy NEP 1, numpy.lib.format; SPEC §11).

namespace vri {

struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<float> data;
};

// Throws vri::Error for anything but a little-endian float32/float64 C-order array.
NpyArray read_npy(const std::filesystem::path& path);
void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const float> data);
// Shape (H, W, 4): the premultiplied (r, g, b, alpha) before any background.
void write_npy(const std::filesystem::path& path, const Image& image);

// A volume from a 3-D array indexed [z, y, x] (SPEC §11): dims are
// (shape[2], shape[1], shape[0]), spacing 1, origin 0. Format versions 1.0,
// 2.0 and 3.0; C or Fortran order (transposed into x-fastest storage); dtypes
// bool (as 0/1), int8..int64, uint8..uint64, float16/32/64 in either byte
// order. uint8 (and bool), uint16, int16 and float32 keep their type, the
// others become float32. Object, string, complex, datetime and structured
// dtypes, and arrays that are not 3-D, are refused with vri::Error naming the
// file, as are data shorter or longer than the shape needs; sizes are checked
// (GridVolume::checked_sample_count, the memory budget) before allocating.
GridVolume read_npy_volume(const std::filesystem::path& path);
// The same from the file's bytes; `source` names it in errors.
GridVolume parse_npy_volume(std::span<const std::byte> bytes, const std::string& source);

}  // namespace vri

// ---- png -------------------------------------------------------------------
// PNG output (SPEC §7): 8-bit RGBA composited over a background, or with
// alpha, or 16 bits a channel.

namespace vri {

// How a PNG holds the image: by default (SPEC §7) each colour channel is
// C + (1 - alpha) bg, clamped to [0, 1] and rounded to the nearest of 0..255,
// alpha 255. `transparent`: no background, the straight colour C / alpha (0
// where alpha is 0) and alpha itself, as PNG's alpha is not premultiplied.
// `bits` 16: the same values rounded to 0..65535.
struct PngFormat {
  bool transparent = false;
  int bits = 8;
};
void write_png(const std::filesystem::path& path, const Image& image, Vec3 background, PngFormat format = {});
// The same PNG file in memory (the viewer's final frames: the same bytes as `vri render -o x.png`).
std::vector<std::byte> encode_png(const Image& image, Vec3 background, PngFormat format = {});

// The composite above as 8-bit RGBA, row 0 at the top (alpha 255).
std::vector<std::uint8_t> composite_rgba8(const Image& image, Vec3 background);
// Pixels (1 channel: grey; 4: RGBA) of 8 bits, or of 16 bits as big-endian
// byte pairs, row 0 at the top, as a PNG file.
std::vector<std::byte> encode_png(std::span<const std::uint8_t> pixels, int width, int height, int channels,
                                  int bits = 8);

}  // namespace vri

// ---- raw_volume ------------------------------------------------------------
// Headerless raw volumes (SPEC §1): nx*ny*nz samples, x fastest.

namespace vri {

// The file must hold exactly nx*ny*nz samples of `type`; a short or oversized
// file is refused, since either means the dims or the type are wrong.
// With `region`, only the region it picks is read (a part, grid_part.hpp).
GridVolume read_raw_volume(const std::filesystem::path& path, std::array<std::int64_t, 3> dims,
                           ScalarType type, Endian endian = Endian::Little, const RegionChooser& region = {});

}  // namespace vri
