#pragma once
// The Vulkan tests' comparison: a scene rendered by the GPU backend against
// the CPU's float path, pixel by pixel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::test {

struct Difference {
  double max = 0;           // max abs, per channel
  std::size_t differing = 0;  // channels that differ at all
};

inline Difference compare(const Image& a, const Image& b) {
  Difference d;
  EXPECT_EQ(a.data().size(), b.data().size());
  for (std::size_t i = 0; i < a.data().size() && i < b.data().size(); ++i) {
    const double e = std::abs(double(a.data()[i]) - double(b.data()[i]));
    d.max = std::max(d.max, e);
    d.differing += e != 0;
  }
  return d;
}

// The share of pixels of a and b differing by more than `bound` in some channel.
inline double share_over(const Image& a, const Image& b, double bound) {
  std::size_t over = 0;
  for (std::size_t i = 0; i < a.data().size(); i += 4) {
    double m = 0;
    for (int c = 0; c < 4; ++c) m = std::max(m, std::abs(double(a.data()[i + c]) - b.data()[i + c]));
    over += m > bound;
  }
  return double(over) / double(a.data().size() / 4);
}

inline double max_alpha(const Image& image) {
  double m = 0;
  for (std::size_t i = 3; i < image.data().size(); i += 4) m = std::max(m, double(image.data()[i]));
  return m;
}

// The GPU's and the CPU's image of `scene`, compared.
inline Difference gpu_against_cpu(const Scene& scene) {
  const Image cpu = SceneRenderer(scene).render({.threads = 2});
  const Image gpu = SceneRenderer(scene, Backend::Vulkan).render({.threads = 2});
  EXPECT_GT(max_alpha(cpu), 0.05) << "the comparison needs something drawn";
  return compare(gpu, cpu);
}

}  // namespace vri::test
