#pragma once
// GradientField (SPEC §5): the gradient at each grid point by central
// differences (one-sided on the border) divided by the spacing, and between
// grid points the trilinear interpolation of those vectors. Stored as 3
// floats per grid point whatever the volume's sample type (docs/PERFORMANCE.md,
// "Peak memory": lighting's memory is out of issue 8's goal).
#include <array>
#include <vector>

#include "vri/memory.hpp"
#include "vri/geometry.hpp"
#include "vri/volume.hpp"

namespace vri {

class GradientField {
 public:
  explicit GradientField(const GridVolume& volume);

  // Gradient at grid point (i, j, k), world units.
  Vec3 at(int i, int j, int k) const;
  // Trilinearly interpolated gradient at a world point (clamped onto the box).
  Vec3 sample(Vec3 p) const;
  // The 8 corner values of component `axis` of cell (i, j, k), in the order
  // c000, c100, c010, c110, c001, c101, c011, c111.
  std::array<double, 8> cell_corners(int axis, std::array<int, 3> cell) const;
  // The stored vectors, 3 floats (x, y, z) per grid point, for the float
  // paths (src/methods/march/float_shading.hpp).
  const float* data() const { return g_.data(); }

 private:
  template <class T>
  void fill(const T* values);  // central differences of the typed samples

  const GridVolume& volume_;
  MemoryCharge charge_;   // g_'s bytes, held against the process's budget
  std::vector<float> g_;  // 3 floats per grid point, x fastest
};

}  // namespace vri
