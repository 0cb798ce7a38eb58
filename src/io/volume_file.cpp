#include "vri/io.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <system_error>
#include <vector>

#include "vri/error.hpp"
#include "io/vtk_legacy.hpp"

namespace vri {

namespace {

std::string_view as_text(std::span<const std::byte> bytes) {
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

bool starts_with(std::string_view text, std::string_view prefix) { return text.substr(0, prefix.size()) == prefix; }

// MetaImage headers are "Key = value" lines; the first key of ITK's and
// VTK's writers is one of these.
bool looks_like_metaimage(std::string_view text) {
  const std::size_t start = text.find_first_not_of(" \t\r\n");
  if (start == std::string_view::npos) return false;
  text.remove_prefix(start);
  for (std::string_view key : {"ObjectType", "NDims", "Comment", "ObjectSubType", "TransformType"})
    if (starts_with(text, key)) {
      const std::size_t eq = text.find('=');
      const std::size_t nl = text.find('\n');
      return eq != std::string_view::npos && (nl == std::string_view::npos || eq < nl);
    }
  return false;
}

}  // namespace

VolumeFormat volume_format(std::span<const std::byte> head, const std::filesystem::path& name) {
  const std::string_view text = as_text(head);
  if (starts_with(text, "NRRD000")) return VolumeFormat::Nrrd;
  if (starts_with(text, "\x93NUMPY")) return VolumeFormat::Npy;
  using namespace std::string_view_literals;
  for (std::string_view magic : {"II*\0"sv, "MM\0*"sv, "II+\0"sv, "MM\0+"sv})
    if (starts_with(text, magic)) return VolumeFormat::Tiff;
  if (starts_with(text, "# vtk DataFile"))
    return vtk_legacy_is_structured_points(head) ? VolumeFormat::VtkStructuredPoints : VolumeFormat::VtkLegacyMesh;
  if (const std::size_t tag = text.find("<VTKFile"); tag != std::string_view::npos) {
    const std::size_t end = text.find('>', tag);
    const std::string_view attrs = text.substr(tag, end == std::string_view::npos ? text.npos : end - tag);
    if (attrs.find("type=\"ImageData\"") != std::string_view::npos) return VolumeFormat::Vti;
    if (attrs.find("type=\"UnstructuredGrid\"") != std::string_view::npos) return VolumeFormat::Vtu;
    throw Error("'" + printable(name.string()) + "': a VTK XML file of a type vri does not read (it reads "
                "ImageData .vti and UnstructuredGrid .vtu)");
  }
  if (looks_like_metaimage(text)) return VolumeFormat::MetaImage;
  std::string ext = name.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".dat") return VolumeFormat::VolvisDat;
  return VolumeFormat::Raw;
}

VolumeFormat volume_format(const std::filesystem::path& path) {
  // A folder holds TIFF slices; otherwise the first KiB, or the whole file if
  // shorter (the same errors as every reader: a missing file, no permission).
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return VolumeFormat::Tiff;
  const std::uint64_t size = checked_file_size(path);
  std::vector<std::byte> head(std::size_t(std::min<std::uint64_t>(size, 1024)));
  read_file_range(path, 0, head);
  return volume_format(head, path);
}

bool is_mesh(VolumeFormat format) { return format == VolumeFormat::VtkLegacyMesh || format == VolumeFormat::Vtu; }

std::string_view format_name(VolumeFormat format) {
  switch (format) {
    case VolumeFormat::Raw: return "raw";
    case VolumeFormat::Nrrd: return "NRRD";
    case VolumeFormat::VolvisDat: return "volvis .dat";
    case VolumeFormat::Vti: return "VTK XML image data";
    case VolumeFormat::VtkStructuredPoints: return "legacy VTK structured points";
    case VolumeFormat::MetaImage: return "MetaImage";
    case VolumeFormat::Npy: return "NumPy";
    case VolumeFormat::Tiff: return "TIFF";
    case VolumeFormat::VtkLegacyMesh: return "legacy VTK unstructured grid";
    case VolumeFormat::Vtu: return "VTK XML unstructured grid";
  }
  return "?";
}

std::string_view supported_formats() {
  return "NRRD (.nrrd, .nhdr), VTK (.vti, .vtk structured points; meshes .vtk, .vtu), MetaImage (.mhd, .mha), "
         "NumPy (.npy), TIFF (.tif, .tiff stacks, or a folder of one-page slices), volvis (.dat), or headerless "
         "raw with 'dims' and 'type'";
}

}  // namespace vri
