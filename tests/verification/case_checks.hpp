#pragma once
// What the verification system asserts on every generated case (issue 46,
// docs/VERIFICATION.md): each check is one documented bound, named, so that
// a campaign counts violations per check and per family.
#include <string>
#include <vector>

#include "verification/case_generator.hpp"

namespace vri::verify {

struct Violation {
  std::string check;   // a Check name below
  std::string method;  // the method (and variant) that broke it
  std::string detail;  // the numbers
};

// The checks, in the order they run:
//  finite        every method renders (no vri::Error, no NaN or infinity)
//  alpha-range   0 <= alpha <= 1 and C >= 0 on every pixel of every method
//  colour-bound  unlit: each colour channel <= alpha (chromaticity <= 1)
//  exact-vs-independent
//                unlit: `exact` within kExactAgainstReference of the
//                independent reference (reference_integral.hpp)
//  guaranteed    adaptive `guaranteed` at 1e-3 within 1e-3 of `exact`
//  threads       preint1 with 1 and 2 threads: the same bytes
//  skipping      riemann, preint1, preint2 with and without empty-space
//                skipping: the same bytes
//  table-convergence
//                preint1 and preint2: the RMS against `exact` does not grow
//                as the step halves from 1 to 0.25 (1e-4 of slack)
//  float-vs-double
//                riemann, preint1, preint2 (step 0.5) and preint2-dual: the
//                float path (packets included) within kFloatAgainstDouble of
//                the double path (`"float_math": false`) on every channel,
//                plus what a scalar error of 1e-6 of the data range moves
//                colour or a step's alpha on the transfer function's
//                steepest segment; skipped where control points (almost)
//                coincide (docs/ARCHITECTURE.md)
struct Checks {
  bool table_convergence = true;
  bool second_order_wins = true;  // preint2's RMS <= preint1's (+1e-4) at each step
};
std::vector<Violation> check_case(const Case& c, const Checks& which = {});

// |exact - reference| allowed per channel: exact's own 1e-6 plus the
// reference's linearisation between its samples.
inline constexpr double kExactAgainstReference = 2e-4;
// |float path - double path| allowed per channel (docs/ARCHITECTURE.md).
inline constexpr double kFloatAgainstDouble = 1e-4;

}  // namespace vri::verify
