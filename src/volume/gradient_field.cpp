#include "volume/gradient_field.hpp"

#include <algorithm>

#include "vri/memory.hpp"

namespace vri {

GradientField::GradientField(const GridVolume& volume)
    : volume_(volume),
      charge_(volume.size(), 3 * sizeof(float), "the lighting gradient field (3 floats per grid point)"),
      g_(3 * volume.size()) {
  volume.visit([this](auto v) { fill(v.data()); });
}

template <class T>
void GradientField::fill(const T* v) {
  const auto& n = volume_.dims();
  const Vec3 sp = volume_.spacing();
  std::size_t idx = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i, ++idx) {
        const int c[3] = {i, j, k};
        for (int a = 0; a < 3; ++a) {
          int lo[3] = {i, j, k}, hi[3] = {i, j, k};
          lo[a] = std::max(c[a] - 1, 0);
          hi[a] = std::min(c[a] + 1, n[a] - 1);
          const double dv = static_cast<float>(v[volume_.index(hi[0], hi[1], hi[2])]) -
                            static_cast<float>(v[volume_.index(lo[0], lo[1], lo[2])]);
          g_[3 * idx + a] = static_cast<float>(dv / ((hi[a] - lo[a]) * sp[a]));
        }
      }
}

Vec3 GradientField::at(int i, int j, int k) const {
  const float* p = g_.data() + 3 * volume_.index(i, j, k);
  return {p[0], p[1], p[2]};
}

std::array<double, 8> GradientField::cell_corners(int axis, std::array<int, 3> c) const {
  std::array<double, 8> out;
  for (int corner = 0; corner < 8; ++corner)
    out[corner] = g_[3 * volume_.index(c[0] + (corner & 1), c[1] + ((corner >> 1) & 1), c[2] + (corner >> 2)) + axis];
  return out;
}

Vec3 GradientField::sample(Vec3 p) const {
  const GridVolume::GridCell cell = volume_.cell_at(volume_.grid_position(p));
  const std::array<int, 3>& c = cell.index;
  const auto& f = cell.f;
  Vec3 out;
  for (int a = 0; a < 3; ++a) {
    const auto v = cell_corners(a, c);
    const double x00 = v[0] + f[0] * (v[1] - v[0]), x10 = v[2] + f[0] * (v[3] - v[2]);
    const double x01 = v[4] + f[0] * (v[5] - v[4]), x11 = v[6] + f[0] * (v[7] - v[6]);
    const double y0 = x00 + f[1] * (x10 - x00), y1 = x01 + f[1] * (x11 - x01);
    out[a] = y0 + f[2] * (y1 - y0);
  }
  return out;
}

}  // namespace vri
