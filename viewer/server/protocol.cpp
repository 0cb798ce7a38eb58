#include "protocol.hpp"

#include <cmath>
#include <cstring>

#include "core/json_support.hpp"
#include "vri/error.hpp"

namespace vri::viewer {

using nlohmann::json;

namespace {

void only_keys(const json& j, std::initializer_list<const char*> keys, const std::string& where) {
  for (const auto& [key, value] : j.items()) {
    bool known = false;
    for (const char* k : keys) known = known || key == k;
    if (!known) throw Error(where + ": unknown key '" + key + "'");
  }
}

const json& member(const json& j, const char* key, json::value_t type, const std::string& where) {
  if (!j.contains(key)) throw Error(where + ": '" + key + "' is missing");
  const json& v = j.at(key);
  const bool ok = type == json::value_t::number_float ? v.is_number() : v.type() == type;
  if (!ok) throw Error(where + ": '" + key + "' has the wrong type");
  return v;
}

// The client may not make the server read files: only the dataset's own volume is rendered.
void refuse_files(const json& j, const std::string& where) {
  if (j.is_object()) {
    if (j.contains("file")) throw Error(where + ": a viewer message may not name a file");
    for (const auto& [key, value] : j.items()) refuse_files(value, where + "." + key);
  } else if (j.is_array()) {
    for (const auto& v : j) refuse_files(v, where);
  }
}

RenderRequest render_request(const json& j) {
  only_keys(j, {"type", "seq", "quality", "scene", "error_map", "refine"}, "render");
  RenderRequest r;
  const json& seq = member(j, "seq", json::value_t::number_float, "render");
  if (!seq.is_number_integer() || seq.get<double>() < 0 || seq.get<double>() > 9.0e15)
    throw Error("render: 'seq' must be a whole number >= 0");
  r.seq = seq.get<std::int64_t>();
  const std::string quality = member(j, "quality", json::value_t::string, "render").get<std::string>();
  if (quality == "preview") r.quality = Quality::Preview;
  else if (quality == "final") r.quality = Quality::Final;
  else throw Error("render: 'quality' must be preview or final, not '" + quality + "'");
  r.scene = member(j, "scene", json::value_t::object, "render");
  only_keys(r.scene, {"transfer_function", "camera", "lighting", "background", "method", "clip"}, "render.scene");
  refuse_files(r.scene, "render.scene");
  const json& camera = member(r.scene, "camera", json::value_t::object, "render.scene");
  for (const char* side : {"width", "height"})
    if (camera.contains(side) && camera.at(side).is_number() &&
        !(camera.at(side).get<double>() <= kMaxFrameSide))
      throw Error("render.scene.camera: '" + std::string(side) + "' over the viewer's " +
                  std::to_string(kMaxFrameSide) + " pixels");
  if (j.contains("error_map")) {
    const json& e = member(j, "error_map", json::value_t::object, "render");
    only_keys(e, {"enabled", "tolerance"}, "render.error_map");
    r.error_map = member(e, "enabled", json::value_t::boolean, "render.error_map").get<bool>();
    if (e.contains("tolerance")) {
      r.error_tolerance = member(e, "tolerance", json::value_t::number_float, "render.error_map").get<double>();
      if (!(r.error_tolerance > 0 && r.error_tolerance < 1))
        throw Error("render.error_map: 'tolerance' must be in (0, 1)");
    }
  }
  if (j.contains("refine")) r.refine = member(j, "refine", json::value_t::boolean, "render").get<bool>();
  return r;
}

}  // namespace

ClientMessage parse_client_message(std::string_view text) {
  if (text.size() > kMaxMessageBytes) throw Error("message over " + std::to_string(kMaxMessageBytes) + " bytes");
  // Before any parse: the checks below walk the value recursively (issue 47).
  if (json_depth(text) > kMaxJsonDepth)
    throw Error("message nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) throw Error("message is not JSON");
  if (!j.is_object()) throw Error("message is not a JSON object");
  const std::string type = member(j, "type", json::value_t::string, "message").get<std::string>();
  if (type == "render") return render_request(j);
  if (type == "open") {
    only_keys(j, {"type", "dataset"}, "open");
    return OpenRequest{member(j, "dataset", json::value_t::string, "open").get<std::string>()};
  }
  throw Error("unknown message type '" + type + "'");
}

std::int64_t seq_of(std::string_view text) {
  if (text.size() > kMaxMessageBytes || json_depth(text) > kMaxJsonDepth) return -1;
  const json j = json::parse(text, nullptr, false);
  if (j.is_object() && j.contains("seq") && j["seq"].is_number_integer()) return j["seq"].get<std::int64_t>();
  return -1;
}

std::string error_message(std::int64_t seq, const std::string& message) {
  // dump() with replacement: a message quoting the client's bytes stays valid UTF-8.
  return json{{"type", "error"}, {"seq", seq}, {"message", message_line(message)}}.dump(-1, ' ', false,
                                                                          json::error_handler_t::replace);
}

std::vector<std::byte> frame_message(const json& header, const std::vector<std::byte>& image) {
  const std::string h = header.dump();
  std::vector<std::byte> out(4 + h.size() + image.size());
  const auto n = static_cast<std::uint32_t>(h.size());
  for (int i = 0; i < 4; ++i) out[i] = std::byte((n >> (8 * i)) & 0xff);
  std::memcpy(out.data() + 4, h.data(), h.size());
  if (!image.empty()) std::memcpy(out.data() + 4 + h.size(), image.data(), image.size());
  return out;
}

}  // namespace vri::viewer
