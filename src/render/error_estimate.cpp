#include "render/error_estimate.hpp"

namespace vri {

namespace {

// Presents the error estimate as the "colour" of each ray, so the ordinary
// renderer (tiles, threads) computes the estimate image.
class EstimateAsColour final : public Integrator {
 public:
  explicit EstimateAsColour(const ErrorEstimatingIntegrator& inner) : inner_(inner) {}
  Rgba integrate(const Ray& ray) const override {
    RayStats stats;
    inner_.integrate(ray, stats);
    return stats.error_estimate;
  }
  std::string_view name() const override { return inner_.name(); }

 private:
  const ErrorEstimatingIntegrator& inner_;
};

}  // namespace

Image render_error_estimate(const Camera& camera, const ErrorEstimatingIntegrator& integrator,
                            const RenderOptions& options) {
  return render(camera, EstimateAsColour(integrator), options);
}

}  // namespace vri
