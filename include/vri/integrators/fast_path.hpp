#pragma once
// FastPath: the speed-ups of the ray casters (riemann, preint1, preint2) that
// change no pixel, or change it by a stated bound (issue 8; docs/PERFORMANCE.md).
// - skip_empty: rays leap over macro cells whose values the transfer function
//   maps to zero opacity (volume/empty_space.hpp); they stay on the same
//   sample positions, so the image is the same bytes as without skipping.
// - termination: a ray stops once its transmittance T falls below this
//   threshold (0: never; SPEC is silent, so it is off unless asked for). What
//   it drops is at most T < termination in alpha, and T times the largest
//   colour (1 for unlit colours) in each colour channel.
// - float_math (riemann, preint1, preint2): sampling, classification or
//   table lookups and shading in float on the same sample positions
//   (integrators/float_riemann.hpp, float_march.hpp, float_shading.hpp),
//   compositing in double (FrontToBack, integrators/ray_steps.hpp: a float
//   sum's roundings grew with the number of samples), on packets of 8 rays
//   with AVX2 (integrators/float_packet.hpp): unlit and lit, in both
//   lighting modes of the pre-integrated methods. A pixel differs from the
//   double path's by under 1e-4 per channel on the bundled scenes, and by
//   under 1e-6 at fine steps (tested). Off: the double path, the reference.
#include <memory>
#include <optional>
#include <string>

#include "vri/render/image.hpp"
#include "vri/tables/zero_opacity.hpp"
#include "vri/volume/empty_space.hpp"
#include "vri/volume/macro_cells.hpp"

namespace vri {

struct FastPath {
  bool skip_empty = true;
  double termination = 0;  // transmittance threshold in [0, 1)
  bool float_math = true;
};

// The bound on what early termination dropped in an image rendered with
// threshold `termination` > 0: a ray stops only once T < termination, and its
// pixel keeps alpha = 1 - T, so every pixel that may have stopped has
// 1 - alpha < termination and lost at most its 1 - alpha (times the largest colour).
struct TerminationBound {
  long long pixels = 0;   // pixels with 1 - alpha < termination: those that may have stopped early
  double max_remaining = 0;  // the largest 1 - alpha among them
};
TerminationBound termination_bound(const Image& image, double termination);

namespace detail {

// What an integrator holds for its fast path: the macro cells of its volume,
// their classification against its transfer function and, to test slabs
// against it, the transfer function's zero-opacity ranges.
class Skipping {
 public:
  // Throws vri::Error unless 0 <= termination < 1.
  Skipping(const GridVolume& volume, ZeroOpacity zero, const FastPath& fast, const std::string& method);
  const EmptySpace* space() const { return space_ ? &*space_ : nullptr; }
  const ZeroOpacity* zero() const { return zero_ ? &*zero_ : nullptr; }  // null without skipping
  double termination() const { return termination_; }
  // Integrator::footprint of a method that skips this way: with skipping,
  // the non-empty macro cells (EmptySpace::occupied_parts; a ray that meets
  // none leaps to its end from its first sample, or reads only zero
  // entries: it adds exactly nothing), else the volume's box.
  const Footprint& footprint() const { return footprint_; }

 private:
  std::unique_ptr<MacroCells> cells_;
  std::optional<ZeroOpacity> zero_;
  std::optional<EmptySpace> space_;
  Footprint footprint_;
  double termination_;
};

}  // namespace detail
}  // namespace vri
