// The verification system's fast tier (issue 46): the first generated cases,
// every check of case_checks.hpp on each. A violation names the seed and the
// scene, so `vri-verify --first SEED --cases 1` replays it. The long
// campaign is scripts/verify.sh (docs/VERIFICATION.md).
#include <gtest/gtest.h>

#include "verification/case_checks.hpp"

namespace vri::verify {
namespace {

class FastTier : public ::testing::TestWithParam<int> {};

// Blocks of 10 seeds, so that ctest spreads them over its jobs.
TEST_P(FastTier, EveryCheckHolds) {
  for (int k = 0; k < 10; ++k) {
    const std::uint64_t seed = std::uint64_t(GetParam()) * 10 + std::uint64_t(k);
    const Case c = make_case(seed);
    // Open class (issue 46, item 2): table methods with features narrower
    // than a bin do not converge as the step halves; reported by the
    // campaign, not asserted until fixed.
    for (const Violation& v : check_case(c, {.table_convergence = false}))
      ADD_FAILURE() << "seed " << seed << ": " << v.check << ", " << v.method << ": " << v.detail << "\n" << c.json;
  }
}

// 100 cases (about 80 s on one core); 30 under AddressSanitizer, which runs
// them several times slower.
#if defined(__SANITIZE_ADDRESS__)
INSTANTIATE_TEST_SUITE_P(Seeds, FastTier, ::testing::Range(0, 3));
#else
INSTANTIATE_TEST_SUITE_P(Seeds, FastTier, ::testing::Range(0, 10));
#endif

}  // namespace
}  // namespace vri::verify
