#pragma once
// MethodSpec: the "method" block of a scene (SPEC §8, §9) - which integrator
// and its parameters. Step sizes are in voxel units (SPEC §1).
#include <string>

namespace vri {

struct MethodSpec {
  std::string name = "exact";
  double step = 1.0;         // riemann, preint*: voxel units
  double tolerance = 1e-6;   // exact, adaptive
  int table_size = 256;      // preint*, pt*
  std::string builder = "incremental";  // preint*: pre-integration table builder
};

}  // namespace vri
