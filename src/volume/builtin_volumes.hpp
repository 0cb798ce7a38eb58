#pragma once
// Generated volumes: the standard test signals, reproducible everywhere.
#include <array>
#include <cstdint>

#include "vri/volume.hpp"

namespace vri {

// Marschner & Lobb (1994), "An evaluation of reconstruction filters for volume
// rendering": rho(x,y,z) = (1 - sin(pi z/2) + alpha (1 + rho_r(sqrt(x^2+y^2)))) / (2 (1 + alpha)),
// rho_r(r) = cos(2 pi f_M cos(pi r / 2)), sampled on [-1,1]^3; values in [0,1].
// The usual parameters are 41^3 samples, f_M = 6, alpha = 0.25.
// Each takes an optional RegionChooser: then only the part it picks is
// generated (a part, grid_part.hpp), with the same values.
GridVolume marschner_lobb(std::array<int, 3> dims = {41, 41, 41}, double f_m = 6.0,
                          double alpha = 0.25, const RegionChooser& region = {});

// Signed distance (in index units) from the grid centre minus `radius`:
// negative inside the sphere, zero on it. radius <= 0 picks a quarter of the
// smallest extent.
GridVolume sphere_distance(std::array<int, 3> dims, double radius = 0, const RegionChooser& region = {});

// Independent uniform values in [0, 1) from a counter-based hash of (seed, index),
// identical on every platform and standard library.
GridVolume random_field(std::array<int, 3> dims, std::uint64_t seed = 1, const RegionChooser& region = {});

}  // namespace vri
