// vri_consumer SCENE.json OUT.npy [WIDTH HEIGHT]: renders a scene through the
// installed vri library (as `vri render` does for a grid scene, at 64x64
// unless told) and prints the library's version and the image's mean alpha.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <variant>

#include <vri/camera.hpp>
#include <vri/error.hpp>
#include <vri/methods.hpp>
#include <vri/io.hpp>
#include <vri/render.hpp>
#include <vri/scene.hpp>
#include <vri/version.hpp>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: %s SCENE.json OUT.npy [WIDTH HEIGHT]\n", argv[0]);
    return 2;
  }
  try {
    vri::Scene scene = vri::load_scene(argv[1]);
    scene.camera.width = argc == 5 ? std::atoi(argv[3]) : 64;
    scene.camera.height = argc == 5 ? std::atoi(argv[4]) : 64;
    const vri::Camera camera(scene.camera);
    // The integrator keeps references into `scene`, which outlives it.
    const std::unique_ptr<vri::Integrator> integrator = std::visit(
        [&](const auto& volume) {
          return vri::make_integrator(scene.method, volume, scene.transfer_function, scene.lighting);
        },
        scene.volume);
    const vri::Image image = vri::render(camera, *integrator);
    vri::write_npy(argv[2], image);

    double alpha = 0;
    for (int y = 0; y < image.height(); ++y)
      for (int x = 0; x < image.width(); ++x) alpha += image.pixel(x, y)[3];
    std::printf("vri %s: %dx%d '%s', mean alpha %.6f\n", vri::kVersion, image.width(), image.height(),
                scene.method.name.c_str(), alpha / (double(image.width()) * image.height()));
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vri_consumer: error: %s\n", e.what());
    return 1;
  }
}
