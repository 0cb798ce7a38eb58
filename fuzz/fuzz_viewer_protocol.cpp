// libFuzzer harness: the viewer's protocol (issue 47). Each input is one
// client message, taken as ClientSession and RenderWorker take it - read and
// checked (protocol.cpp), then a render's scene parsed against the dataset's
// volume and its camera read, as the worker does before building anything -
// and answered with an error reply when refused, which must be one valid
// JSON line. Structure-aware: the custom mutator edits the message as JSON
// (a value replaced, a key added from the protocol's and the scene's words,
// a subtree copied or nested) so most inputs reach past the JSON parser.
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <variant>

#include "fuzz_targets.hpp"
#include "protocol.hpp"
#include "volume/builtin_volumes.hpp"

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

using nlohmann::json;

const vri::Volume& volume() {
  static const vri::Volume v = vri::sphere_distance({12, 10, 8}, 3);
  return v;
}

void answer(std::int64_t seq, const std::string& message) {
  const std::string reply = vri::viewer::error_message(seq, message);
  const json j = json::parse(reply, nullptr, false);
  if (j.is_discarded() || j["type"] != "error" || reply.find('\n') != std::string::npos) __builtin_trap();
}

void dispatch(std::string_view text) {
  vri::viewer::ClientMessage message;
  try {
    message = vri::viewer::parse_client_message(text);
  } catch (const vri::Error& e) {
    return answer(vri::viewer::seq_of(text), e.what());
  }
  const auto* render = std::get_if<vri::viewer::RenderRequest>(&message);
  if (!render) return;
  try {
    vri::parse_scene(render->scene.dump(), volume(), vri::fuzz::work_dir(), "render.scene");
    vri::parse_camera(render->scene.at("camera").dump(), "render.scene");
  } catch (const vri::Error& e) {
    answer(render->seq, e.what());
  }
}

const char* const kWords[] = {"type", "seq", "quality", "scene", "error_map", "refine", "enabled", "tolerance",
                              "transfer_function", "camera", "lighting", "background", "method", "name", "step",
                              "table_size", "iterations", "builder", "eye", "target", "up", "fov_y", "width",
                              "height", "projection", "ortho_height", "points", "file", "dataset", "render", "open",
                              "preview", "final", "preint1", "preint2", "preint2-dual", "exact", "adaptive",
                              "riemann", "ambient", "diffuse", "specular", "shininess", "mode", "sampled"};

json random_value(std::mt19937& rng, int depth) {
  switch (rng() % 10) {
    case 0: return nullptr;
    case 1: return bool(rng() & 1);
    case 2: return std::int64_t(rng()) - (1 << 30);
    case 3: return std::ldexp(double(rng()) / 4294967296.0 - 0.5, int(rng() % 80) - 40);
    case 4: return kWords[rng() % std::size(kWords)];
    case 5: return std::string(rng() % 64, char('a' + rng() % 26));
    case 6: return json::array({random_value(rng, depth + 1), random_value(rng, depth + 1)});
    case 7: return depth > 4 ? json(1e308) : json{{kWords[rng() % std::size(kWords)], random_value(rng, depth + 1)}};
    case 8: return json::array({0, 1, 2, 3, 4});
    default: return 4096 + int(rng() % 3) - 1;
  }
}

// Every value of the document, in order, for picking one.
void collect(json& j, std::vector<json*>& out) {
  out.push_back(&j);
  if (j.is_object() || j.is_array())
    for (auto& v : j) collect(v, out);
}

void mutate(json& doc, std::mt19937& rng) {
  std::vector<json*> nodes;
  collect(doc, nodes);
  json& node = *nodes[rng() % nodes.size()];
  switch (rng() % 6) {
    case 0: node = random_value(rng, 0); break;
    case 1:
      if (node.is_object()) node[kWords[rng() % std::size(kWords)]] = random_value(rng, 0);
      break;
    case 2:
      if (node.is_object() && !node.empty()) node.erase(std::next(node.begin(), rng() % node.size()).key());
      break;
    case 3: node = *nodes[rng() % nodes.size()]; break;  // a copy of another part (may be an ancestor)
    case 4: node = json::array({node}); break;            // nested one level deeper
    default:
      if (node.is_number()) node = node.get<double>() * std::ldexp(1.0, int(rng() % 64) - 32);
      break;
  }
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned seed) {
  std::mt19937 rng(seed);
  json doc = json::parse(data, data + size, nullptr, false);
  if (doc.is_discarded() || rng() % 8 == 0) return LLVMFuzzerMutate(data, size, max_size);
  const int edits = 1 + int(rng() % 3);
  for (int i = 0; i < edits; ++i) mutate(doc, rng);
  const std::string out = doc.dump();
  if (out.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::memcpy(data, out.data(), out.size());
  return out.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vri::fuzz::run([](std::span<const std::byte> bytes) { dispatch(vri::fuzz::text_of(bytes)); }, data, size);
  return 0;
}
