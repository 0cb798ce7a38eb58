#pragma once
// TIFF stacks (issue 20, item 1; SPEC §11: page = z, row = y), read with
// libtiff: one multi-page file (.tif, .tiff, BigTIFF too), or a folder of
// one-page slices.
//
// - Page z of the file (or the z-th slice of the folder) is the plane z; row
//   y of a page is y and column x is x, with no flip: the same array saved as
//   .npy [z, y, x] gives the same volume. (VTK's vtkTIFFReader does the same
//   by default; the Orientation tag is not consulted.)
// - Every page must have the width, height, sample format and bits per
//   sample of the first; one sample per pixel (grey), so RGB and palette
//   images are refused, as are ImageDepth > 1 (SGI volume tiles).
// - Sample types: unsigned and signed integers of 8, 16, 32 and 64 bits,
//   floats of 16, 32 and 64 bits. uint8, uint16, int16 and float32 keep
//   their type, the others become float32 (grid_samples.hpp).
// - Any compression libtiff decodes (none, PackBits, LZW, Deflate, ...),
//   strips or tiles; either byte order.
// - Spacing 1 1 1 and origin 0, except for a stack ImageJ or Fiji saved
//   (its ImageDescription starts "ImageJ="): there x and y are 1 /
//   XResolution and 1 / YResolution and z the description's "spacing=", as
//   Fiji and tifffile read them (another file's dpi is not a voxel size, as
//   ParaView's TIFF reader assumes); a scene's "spacing"/"origin" override.
// Bad input ends in one vri::Error naming the file (and page): libtiff's own
// messages are captured into it, never printed. Sizes are checked before
// anything is allocated (GridVolume::checked_sample_count, the memory
// budget, and the file's bytes times the codec's largest expansion).
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vri/volume.hpp"

namespace vri {

// A multi-page TIFF file, or a folder of slices (tiff_slice_files).
GridVolume read_tiff_volume(const std::filesystem::path& path);
// A multi-page TIFF given as its bytes; `source` names it in errors.
GridVolume parse_tiff_volume(std::span<const std::byte> bytes, const std::string& source);

// The slices of a folder: its regular files named *.tif or *.tiff (any case,
// not starting with '.'), in natural order (s2.tif before s10.tif). vri::Error
// if there are none, or if one is a link to a file outside the folder.
std::vector<std::filesystem::path> tiff_slice_files(const std::filesystem::path& folder);
// Natural order of names: runs of digits compare as numbers (then the
// shorter run first: s2 < s02), the rest byte by byte.
bool natural_less(std::string_view a, std::string_view b);

}  // namespace vri
