#pragma once
// 8-bit RGBA PNG output (SPEC §7): the image composited over a background.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "vri/core/vec3.hpp"
#include "vri/render/image.hpp"

namespace vri {

// Each colour channel is C + (1 - alpha) * bg, clamped to [0, 1] and rounded
// to the nearest of 0..255; the composite is opaque, so alpha is 255.
void write_png(const std::filesystem::path& path, const Image& image, Vec3 background);
// The same PNG file in memory (the viewer's final frames: the same bytes as `vri render -o x.png`).
std::vector<std::byte> encode_png(const Image& image, Vec3 background);

// The composite above as 8-bit RGBA, row 0 at the top (alpha 255).
std::vector<std::uint8_t> composite_rgba8(const Image& image, Vec3 background);
// 8-bit pixels (1 channel: grey; 4: RGBA), row 0 at the top, as a PNG file.
std::vector<std::byte> encode_png(std::span<const std::uint8_t> pixels, int width, int height, int channels);

}  // namespace vri
