#pragma once
// The bundled bucky ball seen from the preset's camera at size x size, with a
// given transfer function, and the RMS alpha error of a method against a
// reference image: shared by the pre-integration tests.
#include <string>

#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::test {

// tf_points: the JSON array of transfer-function points.
inline Scene bucky_scene(const std::string& tf_points, int size) {
  const std::string json = R"({
    "volume": {"file": "data/bucky_32x32x32_uint8.raw", "dims": [32, 32, 32], "type": "uint8"},
    "transfer_function": {"points": )" + tf_points + R"(},
    "camera": {"eye": [73.837, 63.231, 89.748], "target": [15.5, 15.5, 15.5], "up": [0, 0, 1],
               "width": )" + std::to_string(size) + R"(, "height": )" + std::to_string(size) + "}}";
  return parse_scene(json, VRI_SOURCE_DIR);
}

inline double rms_alpha(const Scene& scene, const Image& reference, const MethodSpec& spec) {
  const auto integrator = make_integrator(spec, scene.grid(), scene.transfer_function);
  const Image image = render(Camera(scene.camera), *integrator);
  return compare_images(reference.data(), image.data(), 4, 0.01)[3].rms;
}

}  // namespace vri::test
