#pragma once
// Lighting parameters of a scene (SPEC §5, §9): Blinn-Phong coefficients and,
// for pre-integrated methods, how lighting varies across a slab.
#include <string>

namespace vri {

struct Lighting {
  bool enabled = false;
  double ambient = 0.3, diffuse = 0.7, specular = 0.4, shininess = 32;  // SPEC §5 defaults
  std::string mode = "sampled";  // pre-integrated methods: "sampled" or "interpolated"
};

}  // namespace vri
