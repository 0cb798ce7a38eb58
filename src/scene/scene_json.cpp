#include "scene/scene_json.hpp"

namespace vri {

using nlohmann::json;

json camera_json(const CameraSpec& c) {
  json j = {{"eye", {c.eye.x, c.eye.y, c.eye.z}},
            {"target", {c.target.x, c.target.y, c.target.z}},
            {"up", {c.up.x, c.up.y, c.up.z}},
            {"fov_y", c.fov_y},
            {"width", c.width},
            {"height", c.height},
            {"projection", c.projection == Projection::Perspective ? "perspective" : "orthographic"}};
  if (c.projection == Projection::Orthographic) j["ortho_height"] = c.ortho_height;
  return j;
}

json lighting_json(const Lighting& l) {
  return {{"enabled", l.enabled}, {"ambient", l.ambient},     {"diffuse", l.diffuse},
          {"specular", l.specular}, {"shininess", l.shininess}, {"mode", l.mode}};
}

json transfer_function_json(const TransferFunction& tf) {
  json points = json::array();
  for (const ControlPoint& p : tf.points()) points.push_back({p.s, p.r, p.g, p.b, p.tau});
  return {{"points", points}};
}

}  // namespace vri
