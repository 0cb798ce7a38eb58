#pragma once
// Volume files of every format vri reads (issue 20, item 1; docs/FORMATS.md),
// told apart by their magic bytes first and their extension second, so a
// file is read by what it is, not by what it is called.
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

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
