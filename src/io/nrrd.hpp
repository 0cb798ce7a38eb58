#pragma once
// NRRD volumes (teem's format): attached ".nrrd" and detached ".nhdr" headers,
// raw, gzip and ascii encodings, either endianness.
#include <filesystem>

#include "vri/volume.hpp"

namespace vri {

// Reads a 3D NRRD (or 4D with a leading axis of size 1). Spacing comes from
// `spacings`, or from `space directions`, which must be diagonal (vri grids
// are axis-aligned: rotated or permuted axes are refused); a negative entry
// means the file stores that axis backwards: the samples are mirrored along
// it and the origin moved to the low corner, so every sample sits where the
// file puts it (`space origin` + index * direction; the world box is the
// file's). Origin from `space origin`. NRRD spec: teem.sourceforge.net/nrrd/format.html
// A detached header's `data file` is resolved against the header's folder and
// may not leave it (absolute paths, "..", symlinks out) unless
// allow_outside_paths (the scene volume key "allow_outside_paths").
// With `region`, only the region it picks is read (a part, grid_part.hpp):
// raw data by seeks, gzip read through once; ascii read whole and cut.
struct NrrdOptions {
  bool allow_outside_paths = false;
  RegionChooser region = {};
};
GridVolume read_nrrd(const std::filesystem::path& path, const NrrdOptions& options = {});

enum class NrrdEncoding { Raw, Gzip };
// Writes the samples in their stored type (uchar, ushort, short or float). With a ".nhdr" path the data goes to a detached file
// beside it (".raw" or ".raw.gz").
void write_nrrd(const std::filesystem::path& path, const GridVolume& volume,
                NrrdEncoding encoding = NrrdEncoding::Raw);

}  // namespace vri
