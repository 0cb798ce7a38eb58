#include "render_worker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <new>

#include "frame_encoding.hpp"
#include "transfer_presets.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/methods.hpp"
#include "vri/version.hpp"

namespace vri::viewer {

using nlohmann::json;

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The methods that render the dataset's kind of volume (SPEC §9).
json methods_for(const Dataset& d) {
  const bool grid = std::holds_alternative<GridVolume>(d.volume);
  json names = json::array();
  for (const MethodInfo& m : methods())
    if (grid ? m.grid : m.mesh) names.push_back(m.name);
  return names;
}

}  // namespace

RenderWorker::RenderWorker(DatasetCatalog& catalog, std::string first, WorkerOutput output, int threads,
                           Backend backend, std::uint64_t page_memory)
    : catalog_(catalog), output_(std::move(output)), threads_(threads), backend_(backend),
      account_("the viewer's memory for one page", page_memory) {
  pending_ = OpenRequest{std::move(first)};
  thread_ = std::thread([this] { run(); });
}

RenderWorker::~RenderWorker() {
  request_stop();
  thread_.join();
}

void RenderWorker::request_stop() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
    cancel_.cancel();
  }
  wake_.notify_all();
}

void RenderWorker::submit(ClientMessage message) {
  {
    std::lock_guard lock(mutex_);
    pending_ = std::move(message);
    cancel_.cancel();  // whatever runs is stale now
  }
  wake_.notify_all();
}

void RenderWorker::run() {
  const AccountScope account(account_);
  for (;;) {
    ClientMessage message;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || pending_; });
      if (stop_) return;
      message = std::move(*pending_);
      pending_.reset();
      cancel_.reset();  // under the lock: a submit after this cancels this message's work
    }
    const std::int64_t seq = std::holds_alternative<RenderRequest>(message) ? std::get<RenderRequest>(message).seq : -1;
    try {
      handle(message);
    } catch (const RenderCancelled&) {
      // A newer request is waiting: nothing to say.
    } catch (const std::exception& e) {
      // What failed after a cancel (a cancelled build's leftovers) is stale too.
      if (cancel_.cancelled()) continue;
      output_.text(error_message(seq, dynamic_cast<const std::bad_alloc*>(&e) ? "out of memory" : e.what()));
    }
  }
}

void RenderWorker::handle(const ClientMessage& message) {
  if (const auto* o = std::get_if<OpenRequest>(&message)) return open(o->dataset);
  if (!dataset_) throw Error("no dataset is open");
  render(std::get<RenderRequest>(message));
}

void RenderWorker::open(const std::string& id) {
  dataset_ = catalog_.open(id);
  method_ = {};
  exact_ = {};
  final_.reset();
  reference_.reset();
  json welcome = {{"type", "welcome"},
                  {"version", kVersion},
                  {"datasets", catalog_.list()},
                  {"current", dataset_->id},
                  {"scene", dataset_->scene_json},
                  {"methods", methods_for(*dataset_)},
                  {"presets", transfer_presets(dataset_->volume)}};
  welcome.update(dataset_->description);
  output_.text(welcome.dump());
}

RenderWorker::Prepared& RenderWorker::prepare(Prepared& slot, const json& scene, Backend backend) {
  json without_camera = scene;
  without_camera.erase("camera");
  std::string key = without_camera.dump();
  if (slot.renderer && slot.key == key) return slot;
  const auto start = std::chrono::steady_clock::now();
  slot = {};
  slot.scene = std::make_unique<Scene>(parse_scene(scene.dump(), dataset_->volume, dataset_->base_dir, "render.scene"));
  // The build runs in a group that submit() and request_stop() cancel; a
  // cancelled one leaves the slot empty.
  std::unique_ptr<SceneRenderer> renderer;
  cancel_.run([&] {
    const AccountScope account(account_);  // the task may run on another thread
    renderer = std::make_unique<SceneRenderer>(*slot.scene, backend);
  });
  slot.renderer = std::move(renderer);
  slot.key = std::move(key);
  slot.setup_ms = ms_since(start);
  return slot;
}

void RenderWorker::send_frame(std::int64_t seq, json header, const std::vector<std::byte>& image) {
  header["type"] = "frame";
  header["seq"] = seq;
  output_.frame(seq, frame_message(header, image));
}

void RenderWorker::render(const RenderRequest& request) {
  Prepared& m = prepare(method_, request.scene, backend_);
  // The request's own camera: the prepared scene may be one orbited from.
  const CameraSpec spec = parse_camera(request.scene.at("camera").dump(), "render.scene");
  const RenderOptions options{.threads = threads_, .cancel = cancel_.flag()};
  const Vec3 background = m.scene->background;
  json header = {{"setup_ms", m.setup_ms}, {"method", m.renderer->method_name()}};

  if (request.quality == Quality::Preview) {
    CameraSpec small = spec;
    small.width = std::max(1, int(std::lround(double(spec.width) / preview_scale_)));
    small.height = std::max(1, int(std::lround(double(spec.height) / preview_scale_)));
    const auto start = std::chrono::steady_clock::now();
    const Image image = m.renderer->render(Camera(small), options);
    const double render_ms = ms_since(start);
    // Halve the resolution while previews are over budget; double it back when there is
    // room, up to half the window's (a preview is always reduced).
    if (render_ms > kPreviewBudgetMs && preview_scale_ < 16) preview_scale_ *= 2;
    else if (render_ms < kPreviewBudgetMs / 5 && preview_scale_ > 2) preview_scale_ /= 2;
    const auto encode = std::chrono::steady_clock::now();
    const std::vector<std::byte> jpeg = encode_jpeg(image, background);
    header.update({{"stage", "preview"}, {"format", "jpeg"}, {"width", small.width}, {"height", small.height},
                   {"render_ms", render_ms}, {"encode_ms", ms_since(encode)}});
    send_frame(request.seq, header, jpeg);
    return;
  }

  const std::string final_key = request.scene.dump();
  if (!final_ || final_->key != final_key) {
    final_.reset();
    const auto start = std::chrono::steady_clock::now();
    Image image = m.renderer->render(Camera(spec), options);
    final_ = Rendered{final_key, std::move(image), ms_since(start)};
  }
  auto encode = std::chrono::steady_clock::now();
  const std::vector<std::byte> png = encode_png(final_->image, background);
  header.update({{"stage", "final"}, {"format", "png"}, {"width", spec.width}, {"height", spec.height},
                 {"render_ms", final_->render_ms}, {"encode_ms", ms_since(encode)}});
  send_frame(request.seq, header, png);
  if (!request.error_map && !request.refine) return;

  // When idle: the reference, the scene with `exact` as its method, on the
  // CPU whatever the backend (exact is the CPU's reference; docs/GPU.md).
  json exact_scene = request.scene;
  exact_scene["method"] = {{"name", "exact"}, {"tolerance", kExactTolerance}};
  const std::string reference_key = exact_scene.dump();
  if (!reference_ || reference_->key != reference_key) {
    reference_.reset();
    Prepared& e = prepare(exact_, exact_scene, Backend::Cpu);
    const auto start = std::chrono::steady_clock::now();
    Image image = e.renderer->render(Camera(spec), options);
    reference_ = Rendered{reference_key, std::move(image), ms_since(start)};
  }
  json base = {{"setup_ms", exact_.setup_ms}, {"width", spec.width}, {"height", spec.height},
               {"render_ms", reference_->render_ms}, {"format", "png"}};
  if (request.error_map) {
    encode = std::chrono::steady_clock::now();
    const ErrorMap map = error_map(final_->image, reference_->image, request.error_tolerance);
    json h = base;
    h.update({{"stage", "error_map"}, {"method", header["method"]}, {"encode_ms", ms_since(encode)},
              {"error", {{"tolerance", request.error_tolerance}, {"share_over", map.share_over},
                         {"max", map.max}, {"rms", map.rms}}}});
    send_frame(request.seq, h, map.png);
  }
  if (request.refine) {
    encode = std::chrono::steady_clock::now();
    const std::vector<std::byte> exact_png = encode_png(reference_->image, background);
    json h = base;
    h.update({{"stage", "exact"}, {"method", exact_.renderer->method_name()}, {"encode_ms", ms_since(encode)}});
    send_frame(request.seq, h, exact_png);
  }
}

}  // namespace vri::viewer
