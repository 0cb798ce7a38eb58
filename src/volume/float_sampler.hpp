#pragma once
// FloatSampler: GridVolume::sample's trilinear interpolation for preint1's
// float path (issue 8; docs/PERFORMANCE.md). Positions are in grid units
// u = (p - origin) / spacing, in double, so a sample lands in the grid cell
// GridVolume::sample picks up to 1e-12 voxel; the cell is found with one
// truncation per axis (no division, the reciprocal spacing is kept) and the
// eight corners are read through precomputed strides and interpolated in
// float. The value differs from GridVolume::sample's by a few float roundings
// of the corner values (under 1e-6 of the largest |value|): EmptySpace's
// margin covers it, so skipping stays exact on this path too. It reads the
// volume's typed samples (GridVolume::visit, once per ray or packet), each
// corner converted to float exactly.
#include <algorithm>
#include <array>
#include <cstddef>

#include "vri/geometry.hpp"
#include "vri/volume.hpp"

namespace vri {

class FloatSampler {
 public:
  explicit FloatSampler(const GridVolume& volume)
      : sy_(static_cast<std::size_t>(volume.dims()[0])),
        sz_(static_cast<std::size_t>(volume.dims()[0]) * volume.dims()[1]),
        origin_(volume.origin()),
        inverse_{1 / volume.spacing().x, 1 / volume.spacing().y, 1 / volume.spacing().z} {
    for (int a = 0; a < 3; ++a) {
      top_[a] = volume.dims()[a] - 1;
      last_cell_[a] = volume.dims()[a] - 2;
    }
  }

  // Grid units of a world point, and of a world displacement.
  Vec3 grid(Vec3 p) const {
    return {(p.x - origin_.x) * inverse_.x, (p.y - origin_.y) * inverse_.y, (p.z - origin_.z) * inverse_.z};
  }
  Vec3 grid_step(Vec3 d) const { return {d.x * inverse_.x, d.y * inverse_.y, d.z * inverse_.z}; }

  // The cell of grid position u (clamped onto the box as GridVolume::sample):
  // the offset of its first corner and the float fractions in it.
  struct Cell {
    std::size_t offset;
    float f[3];
  };
  Cell cell(Vec3 u) const {
    int c[3];
    Cell out;
    for (int a = 0; a < 3; ++a) {
      const double x = std::clamp(u[a], 0.0, top_[a]);
      c[a] = std::min(static_cast<int>(x), last_cell_[a]);
      out.f[a] = static_cast<float>(x - c[a]);
    }
    out.offset = static_cast<std::size_t>(c[0]) + sy_ * c[1] + sz_ * c[2];
    return out;
  }
  // Trilinear in a cell's corners c000, c100, c010, c110, c001, ... (x fastest).
  static float interpolate(const std::array<float, 8>& v, const float (&f)[3]) {
    const float c00 = v[0] + f[0] * (v[1] - v[0]);
    const float c10 = v[2] + f[0] * (v[3] - v[2]);
    const float c01 = v[4] + f[0] * (v[5] - v[4]);
    const float c11 = v[6] + f[0] * (v[7] - v[6]);
    const float c0 = c00 + f[1] * (c10 - c00);
    const float c1 = c01 + f[1] * (c11 - c01);
    return c0 + f[2] * (c1 - c0);
  }

  // Trilinear value at grid position u of the volume's samples `values`.
  template <class T>
  float at(const T* values, Vec3 u) const {
    const Cell c = cell(u);
    return interpolate(corners_as_float(values + c.offset, sy_, sz_), c.f);
  }

  // The layout `at` reads, for the ray packets (src/methods/preint/float_packet.cpp).
  std::size_t stride_y() const { return sy_; }
  std::size_t stride_z() const { return sz_; }
  double top(int axis) const { return top_[axis]; }
  int last_cell(int axis) const { return last_cell_[axis]; }

 private:
  std::size_t sy_, sz_;
  Vec3 origin_, inverse_;
  double top_[3];
  int last_cell_[3];
};

}  // namespace vri
