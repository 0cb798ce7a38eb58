#include "kd_bricks.hpp"

#include <string>

#include "vri/error.hpp"

namespace vri::distributed {

KdBricks::KdBricks(std::array<int, 3> dims, int count) {
  if (count < 1) throw Error("the brick count must be at least 1, got " + std::to_string(count));
  split({{0, 0, 0}, {dims[0] - 1, dims[1] - 1, dims[2] - 1}}, count);
}

int KdBricks::split(BrickCells cells, int count) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (count == 1) {
    nodes_[index].brick = static_cast<int>(bricks_.size());
    bricks_.push_back(cells);
    return index;
  }
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (cells.hi[a] - cells.lo[a] > cells.hi[axis] - cells.lo[axis]) axis = a;
  const int n = cells.hi[axis] - cells.lo[axis];
  if (n < count)
    throw Error("the volume is too small for " + std::to_string(count) + " bricks: " + std::to_string(n) +
                " cells across its longest side");
  const int below = count / 2;  // ranks on the low side; the cells in proportion
  const int plane = cells.lo[axis] + static_cast<int>(static_cast<long long>(n) * below / count);
  BrickCells low = cells, high = cells;
  low.hi[axis] = plane;
  high.lo[axis] = plane;
  nodes_[index].axis = axis;
  nodes_[index].plane = plane;
  const int c0 = split(low, below);
  const int c1 = split(high, count - below);
  nodes_[index].child[0] = c0;
  nodes_[index].child[1] = c1;
  return index;
}

std::vector<int> KdBricks::front_to_back(const CameraSpec& camera, Vec3 origin, Vec3 spacing) const {
  const Vec3 view = camera.target - camera.eye;
  std::vector<int> order;
  const auto visit = [&](const auto& self, int i) -> void {
    const Node& node = nodes_[i];
    if (node.brick >= 0) {
      order.push_back(node.brick);
      return;
    }
    const int a = node.axis;
    const double plane = origin[a] + node.plane * spacing[a];
    // The low side first when the eye is below the plane (perspective) or
    // the rays run up the axis (orthographic).
    const bool low_first =
        camera.projection == Projection::Perspective ? camera.eye[a] < plane : view[a] > 0;
    self(self, node.child[low_first ? 0 : 1]);
    self(self, node.child[low_first ? 1 : 0]);
  };
  visit(visit, 0);
  return order;
}

}  // namespace vri::distributed
