// The viewer's messages: what is accepted, what is refused with one line, and
// the binary frame layout the page reads.
#include "protocol.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "vri/error.hpp"

namespace vri::viewer {
namespace {

const char* kScene = R"({"transfer_function": {"points": [[0, 1, 1, 1, 0], [255, 1, 1, 1, 0.1]]},
  "camera": {"eye": [0, 0, 100], "target": [0, 0, 0], "width": 64, "height": 48}, "method": {"name": "preint1"}})";

std::string render_message(const std::string& extra = "", const std::string& scene = kScene) {
  return R"({"type": "render", "seq": 7, "quality": "preview", "scene": )" + scene + extra + "}";
}

std::string refusal(const std::string& text) {
  try {
    parse_client_message(text);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

TEST(Protocol, ReadsARenderRequest) {
  const ClientMessage m =
      parse_client_message(render_message(R"(, "error_map": {"enabled": true, "tolerance": 0.01}, "refine": true)"));
  const auto& r = std::get<RenderRequest>(m);
  EXPECT_EQ(r.seq, 7);
  EXPECT_EQ(r.quality, Quality::Preview);
  EXPECT_TRUE(r.error_map);
  EXPECT_DOUBLE_EQ(r.error_tolerance, 0.01);
  EXPECT_TRUE(r.refine);
  EXPECT_EQ(r.scene["camera"]["width"], 64);
}

TEST(Protocol, ReadsAnOpenRequest) {
  EXPECT_EQ(std::get<OpenRequest>(parse_client_message(R"({"type": "open", "dataset": "bonsai"})")).dataset, "bonsai");
}

TEST(Protocol, RefusesBadMessagesWithOneLine) {
  EXPECT_EQ(refusal("{not json"), "message is not JSON");
  EXPECT_EQ(refusal("[1, 2]"), "message is not a JSON object");
  EXPECT_EQ(refusal(R"({"type": "explode"})"), "unknown message type 'explode'");
  EXPECT_EQ(refusal(R"({"seq": 1})"), "message: 'type' is missing");
  EXPECT_EQ(refusal(R"({"type": "render", "seq": "x", "quality": "final", "scene": {}})"),
            "render: 'seq' has the wrong type");
  EXPECT_EQ(refusal(R"({"type": "render", "seq": -1, "quality": "final", "scene": {}})"),
            "render: 'seq' must be a whole number >= 0");
  EXPECT_EQ(refusal(render_message(R"(, "bogus": 1)")), "render: unknown key 'bogus'");
  EXPECT_EQ(refusal(R"({"type": "render", "seq": 1, "quality": "best", "scene": {}})"),
            "render: 'quality' must be preview or final, not 'best'");
  EXPECT_EQ(refusal(render_message(R"(, "error_map": {"enabled": true, "tolerance": 2})")),
            "render.error_map: 'tolerance' must be in (0, 1)");
  EXPECT_EQ(refusal(R"({"type": "open", "dataset": 3})"), "open: 'dataset' has the wrong type");
}

TEST(Protocol, RefusesScenesThatNameFilesOrHugeFrames) {
  EXPECT_EQ(refusal(render_message("", R"({"transfer_function": {"file": "/etc/passwd"}, "camera": {}})")),
            "render.scene.transfer_function: a viewer message may not name a file");
  EXPECT_EQ(refusal(render_message("", R"({"volume": {"file": "x.raw"}, "camera": {}})")),
            "render.scene: unknown key 'volume'");
  EXPECT_EQ(refusal(render_message("", R"({"camera": {"width": 100000, "height": 10}})")),
            "render.scene.camera: 'width' over the viewer's 4096 pixels");
  EXPECT_EQ(refusal(render_message("", R"({"transfer_function": {}})")), "render.scene: 'camera' is missing");
}

TEST(Protocol, RefusesMessagesOverTheLimit) {
  const std::string big = R"({"type": "open", "dataset": ")" + std::string(kMaxMessageBytes, 'a') + "\"}";
  EXPECT_EQ(refusal(big), "message over 262144 bytes");
}

// Issue 47, defect 1: 100 000 nested brackets crashed the server (a
// recursive walk over the value on the I/O thread's stack).
TEST(Protocol, RefusesDeepNestingBeforeAnyWalk) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(refusal(render_message("", R"({"camera": )" + deep + "}")), "message nested deeper than 100 levels");
  EXPECT_EQ(seq_of(R"({"seq": 4, "x": )" + deep + "}"), -1);
  // Brackets inside strings do not count; 100 levels are still read.
  EXPECT_EQ(refusal(R"({"type": "open", "dataset": ")" + std::string(1000, '[') + "\"}"), "accepted");
  const std::string hundred = std::string(97, '[') + std::string(97, ']');  // under message, scene, camera
  EXPECT_EQ(refusal(render_message("", R"({"camera": {"x": )" + hundred + "}}")).find("nested"), std::string::npos);
  EXPECT_NE(refusal(render_message("", R"({"camera": {"x": [)" + hundred + "]}}")).find("nested"), std::string::npos);
}

TEST(Protocol, FindsTheSeqOfABadMessage) {
  EXPECT_EQ(seq_of(R"({"type": "render", "seq": 12, "quality": "nope"})"), 12);
  EXPECT_EQ(seq_of("garbage"), -1);
}

TEST(Protocol, ErrorRepliesAreJsonEvenForBadBytes) {
  const auto reply = nlohmann::json::parse(error_message(3, "bad \xff byte"));
  EXPECT_EQ(reply["type"], "error");
  EXPECT_EQ(reply["seq"], 3);
}

// Issue 47, defects 4 and 10: an error reply quoting the client's input is
// one short line, not up to 256 KiB of it.
TEST(Protocol, ErrorRepliesAreCapped) {
  const std::string reply = error_message(3, "unknown message type '" + std::string(200000, 'x') + "\n'");
  EXPECT_LT(reply.size(), 1100u);
  EXPECT_EQ(nlohmann::json::parse(reply)["seq"], 3);
}

TEST(Protocol, FramesCarryTheirHeaderLengthLittleEndian) {
  const nlohmann::json header = {{"type", "frame"}, {"seq", 5}};
  const std::vector<std::byte> image = {std::byte{0x89}, std::byte{'P'}};
  const std::vector<std::byte> m = frame_message(header, image);
  const std::string h = header.dump();
  ASSERT_EQ(m.size(), 4 + h.size() + 2);
  const std::uint32_t n = std::uint32_t(m[0]) | std::uint32_t(m[1]) << 8 | std::uint32_t(m[2]) << 16 |
                          std::uint32_t(m[3]) << 24;
  EXPECT_EQ(n, h.size());
  EXPECT_EQ(std::memcmp(m.data() + 4, h.data(), h.size()), 0);
  EXPECT_EQ(m[4 + h.size()], std::byte{0x89});
}

}  // namespace
}  // namespace vri::viewer
