#pragma once
// OpenEXR output (issue 20, item 5): the float image as a scanline EXR of
// FLOAT channels R, G, B, A, premultiplied (EXR's own convention, and vri's
// .npy), before any background, ZIP-compressed. Built when CMake finds
// Debian's libopenexr-dev (VRI_HAVE_OPENEXR); otherwise .exr is refused.
#include <filesystem>

#include "vri/image.hpp"

namespace vri {

bool exr_supported();
// Written atomically (staged, then renamed in); vri::Error if it cannot be.
void write_exr(const std::filesystem::path& path, const Image& image);

}  // namespace vri
