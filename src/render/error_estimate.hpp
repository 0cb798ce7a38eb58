#pragma once
// The per-pixel error estimate of an error-estimating integrator: an image
// whose channels hold, for each of r, g, b and alpha, the sum of the ray's
// accepted error terms (SPEC §7 layout, shape (H, W, 4) as .npy). It is a
// second pass over the image, run by the same renderer, so it is the same
// bytes for any thread count.
#include "vri/camera.hpp"
#include "vri/methods.hpp"
#include "vri/image.hpp"
#include "vri/render.hpp"

namespace vri {

Image render_error_estimate(const Camera& camera, const ErrorEstimatingIntegrator& integrator,
                            const RenderOptions& options = {});

}  // namespace vri
