// The render worker: a welcome first; a final frame that is the bytes `vri
// render` writes for the same scene; previews at reduced resolution; latest
// wins; a bad scene gets an error and the worker goes on; the error map
// against `exact` and the exact frame.
#include "render_worker.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>

#include "frame_encoding.hpp"
#include "vri/io.hpp"

namespace vri::viewer {
namespace {

using nlohmann::json;
const std::filesystem::path kRoot = VRI_SOURCE_DIR;

struct Frame {
  json header;
  std::vector<std::byte> image;
};

// Collects what a worker sends, for the test to wait on.
class Inbox {
 public:
  WorkerOutput output() {
    return {[this](std::string text) { push(json::parse(text), {}); },
            [this](std::int64_t, std::vector<std::byte> m) {
              const std::uint32_t n = std::uint32_t(m[0]) | std::uint32_t(m[1]) << 8 | std::uint32_t(m[2]) << 16 |
                                      std::uint32_t(m[3]) << 24;
              json h = json::parse(std::string(reinterpret_cast<const char*>(m.data()) + 4, n));
              push(h, std::vector<std::byte>(m.begin() + 4 + n, m.end()));
            }};
  }
  // The next message, or a failure after 60 s.
  Frame next() {
    std::unique_lock lock(mutex_);
    if (!cv_.wait_for(lock, std::chrono::seconds(60), [&] { return !messages_.empty(); })) {
      ADD_FAILURE() << "no message from the worker";
      return {};
    }
    Frame f = std::move(messages_.front());
    messages_.pop_front();
    return f;
  }

 private:
  void push(json header, std::vector<std::byte> image) {
    {
      std::lock_guard lock(mutex_);
      messages_.push_back({std::move(header), std::move(image)});
    }
    cv_.notify_all();
  }
  std::mutex mutex_;
  std::condition_variable cv_;
  std::deque<Frame> messages_;
};

RenderRequest request(const json& welcome_scene, std::int64_t seq, Quality quality, int size = 96) {
  RenderRequest r;
  r.seq = seq;
  r.quality = quality;
  r.scene = welcome_scene;
  r.scene["camera"]["width"] = size;
  r.scene["camera"]["height"] = size;
  return r;
}

struct WorkerFixture : ::testing::Test {
  DatasetCatalog catalog{kRoot / "scenes/neghip.json", kRoot / "scenes"};
  Inbox inbox;
  RenderWorker worker{catalog, "neghip", inbox.output(), 2};
  json welcome = inbox.next().header;
};

TEST_F(WorkerFixture, WelcomesWithTheDatasetAndItsScene) {
  EXPECT_EQ(welcome["type"], "welcome");
  EXPECT_EQ(welcome["current"], "neghip");
  EXPECT_EQ(welcome["volume"]["kind"], "grid");
  EXPECT_EQ(welcome["histogram"]["counts"].size(), 256u);
  EXPECT_FALSE(welcome["presets"].empty());
  // The named colour maps follow the bundled presets, over neghip's data range (0..255).
  const json& last = welcome["presets"].back();
  EXPECT_EQ(last["name"], "colormap: rainbow_uniform");
  EXPECT_EQ(last["transfer_function"]["points"].front()[0], 0.0);
  EXPECT_EQ(last["transfer_function"]["points"].back()[0], 255.0);
  // The method menu is the registry's grid methods (vri/methods.hpp), in its order.
  EXPECT_EQ(welcome["methods"], json({"riemann", "preint1", "preint2", "preint2-dual", "adaptive", "exact"}));
}

TEST_F(WorkerFixture, FinalFramesAreTheBytesOfVriRender) {
  // The scene, then the same orbited (tables reused, the camera new): each the
  // bytes of `vri render`'s path (load, SceneRenderer, encode_png) for its scene.
  std::vector<std::byte> previous;
  for (int seq = 1; seq <= 2; ++seq) {
    RenderRequest r = request(welcome["scene"], seq, Quality::Final);
    if (seq == 2) r.scene["camera"]["eye"][0] = r.scene["camera"]["eye"][0].get<double>() + 40;
    worker.submit(r);
    const Frame f = inbox.next();
    ASSERT_EQ(f.header["stage"], "final");
    EXPECT_EQ(f.header["seq"], seq);
    EXPECT_EQ(f.header["format"], "png");
    json file = r.scene;
    file["volume"] = welcome["volume"]["json"];
    const Scene scene = parse_scene(file.dump(), "/", "saved");
    EXPECT_EQ(f.image, encode_png(SceneRenderer(scene).render({.threads = 1}), scene.background));
    EXPECT_NE(f.image, previous);
    previous = f.image;
  }
  EXPECT_EQ(welcome["scene"]["method"]["name"], "preint1");  // neghip.json names exact: the viewer opens with its fast method
}

TEST_F(WorkerFixture, PreviewsAreReducedJpegs) {
  worker.submit(request(welcome["scene"], 1, Quality::Preview, 128));
  const Frame f = inbox.next();
  EXPECT_EQ(f.header["stage"], "preview");
  EXPECT_EQ(f.header["format"], "jpeg");
  EXPECT_LE(f.header["width"].get<int>(), 64);
  EXPECT_EQ(f.header["width"], f.header["height"]);
  EXPECT_EQ(std::to_integer<int>(f.image[0]), 0xff);  // JPEG's SOI marker
  EXPECT_EQ(std::to_integer<int>(f.image[1]), 0xd8);
}

TEST_F(WorkerFixture, LatestRequestWins) {
  // A burst: each request cancels the one before, so the last seq is answered
  // and no answer comes for a request older than one already answered.
  for (int seq = 1; seq <= 20; ++seq) worker.submit(request(welcome["scene"], seq, Quality::Final, 256));
  std::int64_t last = 0;
  while (last != 20) {
    const Frame f = inbox.next();
    ASSERT_EQ(f.header["type"], "frame");
    ASSERT_GT(f.header["seq"].get<std::int64_t>(), last);
    last = f.header["seq"].get<std::int64_t>();
  }
}

TEST_F(WorkerFixture, BadSceneGetsAnErrorAndTheWorkerGoesOn) {
  RenderRequest bad = request(welcome["scene"], 4, Quality::Final);
  bad.scene["method"] = {{"name", "no-such-method"}};
  worker.submit(bad);
  const Frame e = inbox.next();
  EXPECT_EQ(e.header["type"], "error");
  EXPECT_EQ(e.header["seq"], 4);
  EXPECT_NE(e.header["message"].get<std::string>().find("no-such-method"), std::string::npos);
  worker.submit(request(welcome["scene"], 5, Quality::Final));
  EXPECT_EQ(inbox.next().header["stage"], "final");
}

// A clipped scene (SPEC §12 "clip", docs/CLIPPING.md): the final frame is
// `vri render`'s bytes for it, not the unclipped one's; a bad clip gets an
// error reply naming the key.
TEST_F(WorkerFixture, ClippedFramesAreTheBytesOfVriRender) {
  RenderRequest r = request(welcome["scene"], 1, Quality::Final);
  r.scene["clip"] = {{"planes", {{1, 0.2, 0, -30}}}, {"box", {{0, 5, 0}, {60, 50, 40}}}};
  worker.submit(r);
  const Frame f = inbox.next();
  ASSERT_EQ(f.header["stage"], "final");
  json file = r.scene;
  file["volume"] = welcome["volume"]["json"];
  const Scene scene = parse_scene(file.dump(), "/", "saved");
  ASSERT_TRUE(scene.clip().active());
  EXPECT_EQ(f.image, encode_png(SceneRenderer(scene).render({.threads = 1}), scene.background));
  file.erase("clip");
  const Scene whole = parse_scene(file.dump(), "/", "saved");
  EXPECT_NE(f.image, encode_png(SceneRenderer(whole).render({.threads = 1}), whole.background));
  RenderRequest bad = request(welcome["scene"], 2, Quality::Final);
  bad.scene["clip"] = {{"planes", {{0, 0, 0, 1}}}};
  worker.submit(bad);
  const Frame e = inbox.next();
  EXPECT_EQ(e.header["type"], "error");
  EXPECT_NE(e.header["message"].get<std::string>().find("clip.planes[0]: expected a plane [nx, ny, nz, d] whose normal is not 0"),
            std::string::npos)
      << e.header["message"];
}

// `vri view --backend vulkan`: the worker's final frame is the GPU renderer's
// image (on lavapipe, the CPU's bytes too), the error map's reference is the
// CPU's exact; a method not on the GPU gets an error reply and the worker
// goes on.
TEST(WorkerOnTheGpu, FramesComeFromTheVulkanBackend) {
  if (!vulkan_backend_built()) GTEST_SKIP() << "built without the Vulkan backend";
  DatasetCatalog catalog{kRoot / "scenes/neghip.json", kRoot / "scenes"};
  Inbox inbox;
  RenderWorker worker{catalog, "neghip", inbox.output(), 2, Backend::Vulkan};
  const json welcome = inbox.next().header;
  worker.submit(request(welcome["scene"], 1, Quality::Final));
  const Frame f = inbox.next();
  ASSERT_EQ(f.header["stage"], "final") << f.header.dump();
  json file = request(welcome["scene"], 1, Quality::Final).scene;
  file["volume"] = welcome["volume"]["json"];
  const Scene scene = parse_scene(file.dump(), "/", "saved");
  EXPECT_EQ(f.image, encode_png(SceneRenderer(scene, Backend::Vulkan).render({.threads = 1}), scene.background));
  RenderRequest exact = request(welcome["scene"], 2, Quality::Final);
  exact.scene["method"] = {{"name", "exact"}};
  worker.submit(exact);
  const Frame e = inbox.next();
  EXPECT_EQ(e.header["type"], "error");
  EXPECT_NE(e.header["message"].get<std::string>().find("not on the GPU yet"), std::string::npos);
  RenderRequest mapped = request(welcome["scene"], 3, Quality::Final);
  mapped.error_map = true;
  mapped.error_tolerance = 1e-3;
  worker.submit(mapped);
  EXPECT_EQ(inbox.next().header["stage"], "final");
  EXPECT_EQ(inbox.next().header["stage"], "error_map");
}

TEST_F(WorkerFixture, ErrorMapAgainstExactAndTheExactFrame) {
  RenderRequest r = request(welcome["scene"], 9, Quality::Final);
  r.scene["method"] = {{"name", "riemann"}, {"step", 4}};  // coarse: a visible error
  r.error_map = true;
  r.error_tolerance = 1e-3;
  r.refine = true;
  worker.submit(r);
  EXPECT_EQ(inbox.next().header["stage"], "final");
  const Frame map = inbox.next();
  ASSERT_EQ(map.header["stage"], "error_map");
  // The statistics of the same two renders computed here.
  json file = r.scene;
  file["volume"] = welcome["volume"]["json"];
  const Scene coarse = parse_scene(file.dump(), "/", "coarse");
  file["method"] = {{"name", "exact"}, {"tolerance", RenderWorker::kExactTolerance}};
  const Scene exact = parse_scene(file.dump(), "/", "exact");
  const Image reference = SceneRenderer(exact).render();
  const ErrorMap expected = error_map(SceneRenderer(coarse).render(), reference, 1e-3);
  EXPECT_EQ(map.header["error"]["share_over"].get<double>(), expected.share_over);
  EXPECT_EQ(map.header["error"]["max"].get<double>(), expected.max);
  EXPECT_GT(expected.share_over, 0.01);
  EXPECT_EQ(map.image, expected.png);
  const Frame refined = inbox.next();
  ASSERT_EQ(refined.header["stage"], "exact");
  EXPECT_EQ(refined.image, encode_png(reference, exact.background));
}

TEST_F(WorkerFixture, OpensAnotherListedDataset) {
  worker.submit(OpenRequest{"bucky"});
  const json w = inbox.next().header;
  EXPECT_EQ(w["type"], "welcome");
  EXPECT_EQ(w["current"], "bucky");
  worker.submit(OpenRequest{"/etc/passwd"});
  EXPECT_EQ(inbox.next().header["type"], "error");
}

}  // namespace
}  // namespace vri::viewer
