#pragma once
// MethodSpec: the "method" block of a scene (SPEC §8, §9) - which integrator
// and its parameters. Step sizes are in voxel units (SPEC §1).
#include <cstdint>
#include <optional>
#include <string>

#include "vri/integrators/fast_path.hpp"
#include "vri/tables/second_order_table.hpp"  // kDefaultSecondOrderIterations

namespace vri {

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
  // threshold; default 0, off). fast_path.hpp.
  FastPath fast{};
  // Caps checked before rendering (issue 17): samples along one ray and
  // samples in all (per ray x pixels); raised by max_samples / max_work.
  double max_samples = 1e7, max_work = 2e10;
  // riemann: the seed of the per-pixel jitter of the first sample (issue 20;
  // riemann.hpp), against wood-grain rings; none: no jitter.
  std::optional<std::uint64_t> jitter{};
};

}  // namespace vri
