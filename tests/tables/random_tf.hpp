#pragma once
// Random piecewise-linear transfer functions for the table tests: narrow
// spikes (1-3 table bins wide, tall), steps, and runs of zero opacity.
#include <random>
#include <vector>

#include "vri/transfer_function.hpp"

namespace vri::test {

// Control points on [0, 255]; `max_tau` bounds the extinction per world unit.
inline TransferFunction random_spiky_tf(unsigned seed, double max_tau) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ControlPoint> pts;
  pts.push_back({0, u(rng), u(rng), u(rng), 0});
  double s = 0;
  while (s < 200) {  // one round adds at most 51, so s stays below 255
    s += 1 + 25 * u(rng);
    const double kind = u(rng);
    if (kind < 0.3) {  // a zero-opacity run
      pts.push_back({s, u(rng), u(rng), u(rng), 0});
      s += 5 + 20 * u(rng);
      pts.push_back({s, u(rng), u(rng), u(rng), 0});
    } else if (kind < 0.6) {  // a narrow spike
      const double w = 0.3 + 2 * u(rng);
      pts.push_back({s, u(rng), u(rng), u(rng), 0});
      pts.push_back({s + w, u(rng), u(rng), u(rng), max_tau * (0.5 + 0.5 * u(rng))});
      pts.push_back({s + 2 * w, u(rng), u(rng), u(rng), 0});
      s += 2 * w;
    } else if (kind < 0.7) {  // a step
      pts.push_back({s, u(rng), u(rng), u(rng), max_tau * u(rng)});
      pts.push_back({s, u(rng), u(rng), u(rng), max_tau * u(rng)});
    } else {
      pts.push_back({s, u(rng), u(rng), u(rng), max_tau * u(rng) * 0.3});
    }
  }
  pts.push_back({255, u(rng), u(rng), u(rng), max_tau * 0.1 * u(rng)});
  return TransferFunction(pts);
}

}  // namespace vri::test
