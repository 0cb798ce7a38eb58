#pragma once
// Sort-last decomposition (docs/DISTRIBUTED.md): a grid's cells cut into N
// bricks by a k-d tree, each split across the longest axis of its node in
// proportion to the ranks on either side, and the bricks' front-to-back
// order for a camera, read off the tree as a BSP tree (Fuchs, Kedem &
// Naylor 1980): at each split the side holding the eye comes first.
#include <array>
#include <vector>

#include "vri/camera.hpp"
#include "vri/geometry.hpp"

namespace vri::distributed {

// One brick: the cells [lo, hi) on each axis it owns (cell i lies between
// grid points i and i + 1).
struct BrickCells {
  std::array<int, 3> lo, hi;
};

class KdBricks {
 public:
  // Throws vri::Error when some brick would own no cell (more ranks than the
  // longest axis of a node has cells).
  KdBricks(std::array<int, 3> dims, int count);

  int count() const { return static_cast<int>(bricks_.size()); }
  const BrickCells& brick(int i) const { return bricks_[i]; }
  // Brick indices front to back as `camera` sees them: from its eye
  // (perspective) or along its view direction (orthographic), for a grid
  // with the given origin and spacing.
  std::vector<int> front_to_back(const CameraSpec& camera, Vec3 origin, Vec3 spacing) const;

 private:
  struct Node {
    int axis = -1, plane = 0;  // the split: cells below `plane` go to child 0
    int child[2] = {-1, -1};
    int brick = -1;  // a leaf's brick
  };
  int split(BrickCells cells, int count);  // the node's index
  std::vector<Node> nodes_;
  std::vector<BrickCells> bricks_;
};

}  // namespace vri::distributed
