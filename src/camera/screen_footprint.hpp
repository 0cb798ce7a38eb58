#pragma once
// ScreenFootprint: the pixels whose rays may meet a method's footprint
// (Integrator::footprint), so that the renderer casts no ray that is known
// to miss it. VTK's ray casters do the same with the projected volume's row
// bounds (vtkFixedPointVolumeRayCastMapper).
//
// A convex box in front of the eye is seen inside the convex hull of its 8
// corners' projections (Camera::project); a pixel is kept where its centre
// lies within a pixel of that hull, a margin far above the rounding of the
// rays and of the clipping. Where a corner lies at or behind the eye's plane
// (or projects to no finite point) every pixel is kept: a perspective eye
// inside the box, or an orthographic image plane through it. The hull is
// the footprint's bounds, asked for row by row (rows); its parts, each
// projected to the rectangle around its corners, mark blocks of 4 x 2
// pixels (sees): a ray between the parts (in a concave or hollow
// footprint) is not cast either.
#include <array>
#include <vector>

#include "vri/camera.hpp"
#include "vri/geometry.hpp"

namespace vri {

class ScreenFootprint {
 public:
  ScreenFootprint(const Camera& camera, const Footprint& footprint);
  // The whole image.
  explicit ScreenFootprint(const Camera& camera);

  // The pixels x0 <= x < x1 of the rows y0 <= y < y1 (x0 >= x1: none) that
  // may see the box.
  struct Span {
    int x0, x1;
  };
  Span rows(int y0, int y1) const;
  // Whether any of the pixels x0 <= x < x1, y0 <= y < y1 may see a part.
  bool sees(int x0, int x1, int y0, int y1) const;

 private:
  int width_, height_;
  bool all_ = true;
  std::vector<std::array<double, 2>> hull_;  // counter-clockwise, in continuous pixel coordinates
  // The blocks of 4 x 2 pixels (from pixel 0, 0) that a part's rectangle
  // reaches, a byte each; empty: every block.
  int blocks_x_ = 0;
  std::vector<unsigned char> blocks_;
};

}  // namespace vri
