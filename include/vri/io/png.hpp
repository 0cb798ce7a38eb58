#pragma once
// 8-bit RGBA PNG output (SPEC §7): the image composited over a background.
#include <filesystem>

#include "vri/core/vec3.hpp"
#include "vri/render/image.hpp"

namespace vri {

// Each colour channel is C + (1 - alpha) * bg, clamped to [0, 1] and rounded
// to the nearest of 0..255; the composite is opaque, so alpha is 255.
void write_png(const std::filesystem::path& path, const Image& image, Vec3 background);

}  // namespace vri
