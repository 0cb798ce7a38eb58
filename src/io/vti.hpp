#pragma once
// VTK XML image data (.vti) as ParaView and VTK write them: one Piece;
// DataArrays in format "ascii", inline "binary" (base64) or "appended" (raw or
// base64 encoding), optionally compressed by vtkZLibDataCompressor or
// vtkLZ4DataCompressor (with liblz4), with
// UInt32 or UInt64 headers, either byte order. The grid: the Piece's Extent
// (which may start anywhere: the volume's origin is Origin + start * Spacing),
// Spacing and Origin. A Direction that is diagonal with entries of +-1 is
// honoured by flipping the data along each reversed axis, so the volume keeps
// positive spacing and covers the same world box (a negative Spacing is read
// the same way); any other Direction is refused (vri grids are axis-aligned). The field is a one-component PointData
// array of any numeric type chosen by name; uint8, uint16, int16 and float32
// keep their type, the others become float. A file whose scalars are cell
// data (CellData, no point scalars, or the one asked for) is the grid of its
// cells' centres: one point fewer a side, its origin half a step in.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "vri/volume.hpp"

namespace vri {

// scalars: the PointData array to use; empty picks the PointData's Scalars
// (active) array, else the first one-component array.
// Throws vri::Error with one line naming the file and the problem.
GridVolume read_vti(const std::filesystem::path& path, const std::string& scalars = "");
GridVolume parse_vti(std::span<const std::byte> bytes, const std::string& scalars, const std::string& source);

}  // namespace vri
