#pragma once
// A camera that frames a box: what a viewer shows first for a volume opened
// without a scene (ParaView's and VTK's ResetCamera: looking down -z with +y
// up, the box's bounding sphere filling the field of view).
#include "vri/camera/camera.hpp"
#include "vri/core/vec3.hpp"

namespace vri {

// Perspective camera of `fov_y` degrees and `width` x `height` pixels whose
// view holds the sphere around the box [lo, hi]: the eye on the +z axis through
// the box's centre, at the distance where the sphere touches the narrower side
// of the view.
CameraSpec frame_box(Vec3 lo, Vec3 hi, int width = 512, int height = 512, double fov_y = 30);

}  // namespace vri
