#pragma once
// The viewer's WebSocket protocol (docs/VIEWER.md, "Protocol"): the client's
// messages, read and checked, and the server's replies and frames, written.
// Pure functions: the session state and the network are elsewhere.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace vri::viewer {

// Largest message a client may send, and the largest frame it may ask for.
inline constexpr std::size_t kMaxMessageBytes = 256 * 1024;
inline constexpr int kMaxFrameSide = 4096;

enum class Quality { Preview, Final };

// {"type": "render", ...}: render the scene (a scene file without its volume).
struct RenderRequest {
  std::int64_t seq = 0;
  Quality quality = Quality::Final;
  nlohmann::json scene;  // transfer_function, camera, lighting, background, method
  bool error_map = false;
  double error_tolerance = 1e-3;
  bool refine = false;  // send the exact image too, when idle
};

// {"type": "open", "dataset": ID}: switch to another dataset of the list.
struct OpenRequest {
  std::string dataset;
};

using ClientMessage = std::variant<RenderRequest, OpenRequest>;

// Reads one client message; vri::Error with one line saying what is wrong
// (not JSON, an unknown type or key, a value of the wrong kind, a scene that
// names a file, a frame over kMaxFrameSide). The scene's own values are
// checked later by the scene loader, as `vri render` checks a file.
ClientMessage parse_client_message(std::string_view text);

// The seq of a message that failed to parse, if it has a readable one (for the error reply).
std::int64_t seq_of(std::string_view text);

// {"type": "error", "seq": seq, "message": message}
std::string error_message(std::int64_t seq, const std::string& message);

// A binary frame: 4-byte little-endian header length, the JSON header, the image file.
std::vector<std::byte> frame_message(const nlohmann::json& header, const std::vector<std::byte>& image);

}  // namespace vri::viewer
