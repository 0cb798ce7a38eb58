#pragma once
// Parameters of the `adaptive` method (SPEC §9).
#include <string>

namespace vri {

enum class AdaptiveStrategy {
  Coupled,     // Campagnolo et al. 2015: the outer step starts from the inner one
  Decoupled,   // Campagnolo et al. 2015: the outer step keeps its own pace
  Guaranteed,  // vri: pieces split at cell faces and TF control points, shared budget
};

// Parses "coupled" / "decoupled" / "guaranteed"; throws vri::Error otherwise.
AdaptiveStrategy parse_adaptive_strategy(const std::string& name);

struct AdaptiveParams {
  double tolerance = 1e-3;
  double h0 = 0.5, hmin = 0.1, hmax = 2.0;  // voxel units (SPEC §1)
  AdaptiveStrategy strategy = AdaptiveStrategy::Coupled;
  // Throws vri::Error unless 1e-9 <= tolerance <= 0.5 and 1e-3 <= hmin <= h0 <= hmax <= 1e3.
  void validate() const;
};

}  // namespace vri
