#pragma once
// Trilinear interpolation in an (N, N, N, 4) array of RGBA entries at
// continuous indices, shared by the float32 and the compact second-order
// tables (the element type is all that differs).
#include <algorithm>
#include <cstddef>

#include "vri/geometry.hpp"

namespace vri {

template <class T>
Rgba trilinear_rgba(const T* data, int n, double u_f, double u_m, double u_b) {
  const double u[3] = {u_f, u_m, u_b};
  int i[3];
  double w[3];
  for (int a = 0; a < 3; ++a) {
    i[a] = std::min(static_cast<int>(u[a]), n - 2);
    w[a] = u[a] - i[a];
  }
  Rgba out{};
  for (int corner = 0; corner < 8; ++corner) {
    double weight = 1;
    std::size_t index = 0;
    for (int a = 0; a < 3; ++a) {
      const int bit = (corner >> (2 - a)) & 1;
      weight *= bit ? w[a] : 1 - w[a];
      index = index * n + i[a] + bit;
    }
    for (int c = 0; c < 4; ++c) out[c] += weight * static_cast<double>(data[4 * index + c]);
  }
  return out;
}

}  // namespace vri
