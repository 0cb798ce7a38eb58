#pragma once
// PNG output (SPEC §7): 8-bit RGBA composited over a background, or with
// alpha, or 16 bits a channel.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "vri/core/vec3.hpp"
#include "vri/image.hpp"

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
