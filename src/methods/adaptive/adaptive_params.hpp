#pragma once
// Parameters of the `adaptive` method (SPEC §9), and its constructors.
#include <memory>
#include <string>

#include "vri/methods.hpp"  // the constructors' types

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

// The registry's constructors (src/methods/method_registry.cpp): the
// integrator of the scene's strategy (AdaptiveSimpsonIntegrator or
// GuaranteedAdaptiveIntegrator) from its method block, and its GPU renderer
// (vulkan_adaptive.cpp, Vulkan builds only).
std::unique_ptr<Integrator> make_adaptive(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                          const Lighting& lighting);
std::unique_ptr<GpuSceneRenderer> make_vulkan_adaptive(const Scene& scene);

}  // namespace vri
