#pragma once
// MetaImage volumes (ITK's MetaIO format, https://itk.org/Wiki/ITK/MetaIO/Documentation):
// a text header of "Key = Value" lines; ".mha" holds the data after the
// header (ElementDataFile = LOCAL), ".mhd" names a data file beside it.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "vri/volume.hpp"

namespace vri {

// What is read:
// - ObjectType Image (when given), NDims 3, DimSize, ElementNumberOfChannels 1;
// - ElementType MET_CHAR, MET_UCHAR, MET_SHORT, MET_USHORT, MET_INT,
//   MET_UINT, MET_LONG, MET_ULONG (4 bytes, as MetaIO has them),
//   MET_LONG_LONG, MET_ULONG_LONG, MET_FLOAT, MET_DOUBLE; uint8, uint16,
//   int16 and float32 keep their type, the others become float32;
// - ElementSpacing (else ElementSize), Offset (or Origin, Position): the
//   position of the file's first sample;
// - BinaryData True (ASCII data are refused), BinaryDataByteOrderMSB or
//   ElementByteOrderMSB; CompressedData True (zlib) with CompressedDataSize
//   (else the rest of the data file); HeaderSize n (the data start n bytes
//   into the data file, MetaIO's rule, also for LOCAL) or -1 (the data are
//   the data file's last bytes);
// - TransformMatrix (or Orientation, Rotation, Direction): a diagonal of ±1
//   only. A -1 means the file stores that axis backwards: the samples are
//   mirrored along it and the origin moved to the low corner, so each sample
//   sits where the file puts it (Offset + Direction * index * spacing) and
//   the world box is the one the file describes. Any other matrix (a
//   rotation, a permutation, a scale) is refused;
// - ElementDataFile: LOCAL, or a file name resolved against the header's
//   folder that may not leave it unless allow_outside_paths (as NRRD's
//   `data file`); LIST and file patterns (%d) are refused.
// Unknown keys (AnatomicalOrientation, CenterOfRotation, user fields) are
// ignored. Every error is one vri::Error line naming the file; sizes are
// checked against the bytes present and the memory budget before allocating.
struct MetaImageOptions {
  bool allow_outside_paths = false;
};
GridVolume read_metaimage(const std::filesystem::path& path, const MetaImageOptions& options = {});
// The same from a header's bytes (an .mha with its data, or an .mhd);
// `base_dir` is where a named data file is looked for, `source` names the
// header in errors.
GridVolume parse_metaimage(std::span<const std::byte> bytes, const std::filesystem::path& base_dir,
                           const std::string& source, const MetaImageOptions& options = {});

}  // namespace vri
