#pragma once
// MethodSpec: the "method" block of a scene (SPEC §8, §9) - which integrator
// and its parameters. Step sizes are in voxel units (SPEC §1).
#include <cstdint>
#include <optional>
#include <string>

namespace vri {

// preint2*: chords per second-order table entry (El Hajjar et al.'s K) unless a scene says.
inline constexpr int kDefaultSecondOrderIterations = 8;

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
//   (methods/riemann/float_riemann.hpp, float_march.hpp, float_shading.hpp),
//   compositing in double (FrontToBack, methods/march/ray_steps.hpp: a float
//   sum's roundings grew with the number of samples), on packets of 8 rays
//   with AVX2 (methods/march/float_packet.hpp): unlit and lit, in both
//   lighting modes of the pre-integrated methods. A pixel differs from the
//   double path's by under 1e-4 per channel on the bundled scenes, and by
//   under 1e-6 at fine steps (tested). Off: the double path, the reference.
struct FastPath {
  bool skip_empty = true;
  double termination = 0;  // transmittance threshold in [0, 1)
  bool float_math = true;
};


struct MethodSpec {
  std::string name = "exact";
  double step = 1.0;         // riemann, preint*: voxel units
  double tolerance = 1e-6;   // exact, adaptive
  int table_size = 256;      // preint*, pt*
  bool table_size_given = false;  // named by the scene or a flag; else preint2-dual uses its own default (64)
  int iterations = kDefaultSecondOrderIterations;  // preint2*: chords per second-order table entry (1..4096)
  int length_samples = 64;   // pt, tet-raycast: lengths in the (l, s_f, s_b) table
  int planes = 0;            // pt-cylindrical: cylinder planes (0: table_size)
  // adaptive (Campagnolo et al. 2015 defaults), voxel units; strategy:
  // coupled, decoupled or guaranteed
  double h0 = 0.5, hmin = 0.1, hmax = 2.0;
  std::string strategy = "coupled";
  // preint*: pre-integration table builder. preint2* use it when it names a
  // second-order builder (plain, fast), else the fast one.
  std::string builder = "incremental";
  // riemann, preint1, preint2: empty-space skipping (`skip_empty`, default on: it changes
  // no pixel) and early ray termination (`termination`, a transmittance
  // threshold; default 0, off). FastPath above.
  FastPath fast{};
  // Caps checked before rendering (issue 17): samples along one ray and
  // samples in all (per ray x pixels); raised by max_samples / max_work.
  double max_samples = 1e7, max_work = 2e10;
  // riemann: the seed of the per-pixel jitter of the first sample (issue 20;
  // riemann.hpp), against wood-grain rings; none: no jitter.
  std::optional<std::uint64_t> jitter{};
};

}  // namespace vri
