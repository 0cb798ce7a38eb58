#pragma once
// An independent reference for SPEC §1, §3 and §4 (unlit), written apart
// from src/: its own trilinear sampling, its own transfer function from the
// control points and its own integration. The ray is sampled every
// kReferenceStep of the smallest spacing; between samples the scalar is
// taken as linear, and on each piece where the transfer function is linear
// too the optical depth is a quadratic in closed form and the colour
// integral Gauss-Legendre on panels of at most half an optical depth, up to
// depth 40 past which nothing shows (e^-40 < 5e-18). So spikes of any width
// and extinctions up to 1e15 are integrated as well as the linearisation
// between samples allows (its error falls as the step squared).
#include "vri/core/rgba.hpp"
#include "vri/render/image.hpp"
#include "vri/scene/scene.hpp"

namespace vri::verify {

inline constexpr double kReferenceStep = 0.01;

// The image of an unlit grid scene, premultiplied RGBA as vri's.
Image reference_image(const Scene& scene);

}  // namespace vri::verify
