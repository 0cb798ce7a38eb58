// The verification system's fast tier (issue 46): the first generated cases,
// every check of case_checks.hpp on each. A violation names the seed and the
// scene, so `vri-verify --first SEED --cases 1` replays it. The long
// campaign is scripts/verify.sh (docs/VERIFICATION.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "verification/case_checks.hpp"

namespace vri::verify {
namespace {

// How many cases: VRI_VERIFY_CASES, else 100 (about 5 minutes of one core;
// 30 under AddressSanitizer, several times slower). The test command runs
// 100 in the Release build and fewer in the others (scripts/test.sh).
int cases() {
  if (const char* v = std::getenv("VRI_VERIFY_CASES"); v && *v) return std::stoi(v);
#if defined(__SANITIZE_ADDRESS__)
  return 30;
#else
  return 100;
#endif
}

class FastTier : public ::testing::TestWithParam<int> {};

// Blocks of 10 seeds, so that ctest spreads them over its jobs.
TEST_P(FastTier, EveryCheckHolds) {
  if (GetParam() * 10 >= cases()) GTEST_SKIP() << "VRI_VERIFY_CASES=" << cases();
  for (int k = 0; k < 10 && GetParam() * 10 + k < cases(); ++k) {
    const std::uint64_t seed = std::uint64_t(GetParam()) * 10 + std::uint64_t(k);
    const Case c = make_case(seed);
    // Open class (issue 46, item 2): table methods with features narrower
    // than a bin do not converge as the step halves; reported by the
    // campaign, not asserted until fixed.
    for (const Violation& v : check_case(c, {.table_convergence = false, .second_order_wins = false}))
      ADD_FAILURE() << "seed " << seed << ": " << v.check << ", " << v.method << ": " << v.detail << "\n" << c.json;
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, FastTier, ::testing::Range(0, 10));

}  // namespace
}  // namespace vri::verify
