#pragma once
// The verification system's generator of hard cases (issue 46): from a seed,
// a scene nobody wrote down - a volume (random field, sphere, Marschner-Lobb,
// a two-slice-thin grid, uneven spacing), a transfer function from a grammar
// (steps at the first or last point or all at one scalar, coincident and
// near-coincident points, spikes down to 1e-3 scalar units wide, 2 to 500
// points, extinctions from 1e-6 to 1e15, colour that changes where the
// extinction is ~0) and a camera (outside, inside, grazing, orthographic
// along a grid axis), sometimes lit with shininess up to 1e3, sometimes
// clipped (oblique, cell-face and grazing planes, crop boxes). The same seed
// gives the same case on every machine (its own counter-based random numbers).
#include <cstdint>
#include <string>
#include <vector>

#include "vri/scene.hpp"

namespace vri::verify {

struct Case {
  std::uint64_t seed = 0;
  // The families it belongs to, one per axis of the grammar: "volume:...",
  // "tf:...", "extinction:...", "camera:...", "light:...", "clip:...".
  std::vector<std::string> families;
  Scene scene;
  // The case as a scene file (the volume named by how to make it), so that a
  // failure can be replayed by hand.
  std::string json;
};

// Side of the generated images: small, so that a case takes milliseconds.
inline constexpr int kImageSide = 12;

Case make_case(std::uint64_t seed);

}  // namespace vri::verify
