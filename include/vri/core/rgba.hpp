#pragma once
// Rgba: one pixel's premultiplied (C, alpha) of SPEC §4, in double precision.
#include <array>

namespace vri {

using Rgba = std::array<double, 4>;

}  // namespace vri
