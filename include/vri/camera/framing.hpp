#pragma once
// Cameras made from the volume instead of written by hand (issue 20, item 3):
// a camera that frames a box, as ParaView's and VTK's "reset camera" do, and
// VTK's camera motions (Azimuth, Elevation, Roll, Zoom) relative to it.
#include "vri/camera/camera.hpp"
#include "vri/core/vec3.hpp"

namespace vri {

// `spec` (its size, fov_y, projection and up kept) looking at the centre of the
// box [lo, hi] from the side that up allows - from +z (looking down -z), or,
// when up is within 25 degrees of the z axis, from -y (looking along +y) - at the
// distance where the box's bounding sphere touches the narrower side of the
// view; orthographic: ortho_height the sphere's diameter.
CameraSpec frame_box(Vec3 lo, Vec3 hi, CameraSpec spec = {});

// VTK's camera motions, in this order, about the target (degrees): azimuth
// turns the eye about `up` (to the right for positive angles), elevation
// raises it towards `up` (up turns with it, so 90 degrees looks straight down
// without a degenerate camera: VTK would need OrthogonalizeViewUp), roll turns
// `up` about the view direction; zoom magnifies by `zoom` as VTK's Zoom does:
// the field of view narrows (tan(fov_y/2) / zoom), or ortho_height / zoom.
CameraSpec move_camera(CameraSpec spec, double azimuth, double elevation, double roll, double zoom);

}  // namespace vri
