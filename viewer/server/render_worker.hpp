#pragma once
// RenderWorker: one client's renders on a thread of their own, latest wins.
// A new request replaces the one waiting and cancels the one in flight (the
// renderer stops between tiles), so no frame the user will not see is
// rendered to the end. For a render request it sends, in turn: a preview
// (reduced resolution, JPEG) or the final frame (full resolution, PNG); then,
// after a final frame and when asked, the error map against `exact` and the
// exact image. Tables, macro cells and images are reused while the transfer
// function and method stay the same (orbiting rebuilds nothing). A table build
// is cancelled too (its TBB group), and what one page's renders hold is
// charged to an account of its own (kPageMemory, server_limits.hpp).
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "vri/memory.hpp"
#include "vri/render.hpp"

#include "dataset.hpp"
#include "server_limits.hpp"
#include "protocol.hpp"
#include "vri/image.hpp"

namespace vri::viewer {

// Where a worker's output goes; called on the worker's thread.
struct WorkerOutput {
  std::function<void(std::string)> text;                                // welcome, error
  std::function<void(std::int64_t seq, std::vector<std::byte>)> frame;  // a binary frame of request seq
};

class RenderWorker {
 public:
  // Sends the welcome of `first` once started. `threads`: render threads (0: every core).
  // `page_memory`: what its tables and images may hold at once.
  RenderWorker(DatasetCatalog& catalog, std::string first, WorkerOutput output, int threads = 0,
               Backend backend = Backend::Cpu, std::uint64_t page_memory = kPageMemory);
  ~RenderWorker();  // cancels the work in flight and joins
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  void submit(ClientMessage message);
  // Cancels the work in flight and ends the thread soon; returns at once
  // (the destructor joins). Nothing is sent after it.
  void request_stop();

  // The longest a preview may take (ms) before the worker halves its resolution again.
  static constexpr double kPreviewBudgetMs = 40;
  // The reference of the error map.
  static constexpr double kExactTolerance = 1e-5;

 private:
  // A scene ready to render: its renderer built (tables, macro cells).
  struct Prepared {
    std::string key;  // the scene JSON without the camera
    std::unique_ptr<Scene> scene;
    std::unique_ptr<SceneRenderer> renderer;
    double setup_ms = 0;
  };
  // A rendered full-resolution image and the scene JSON (with camera) that made it.
  struct Rendered {
    std::string key;
    Image image;
    double render_ms = 0;
  };

  void run();
  void handle(const ClientMessage& message);
  void open(const std::string& id);
  void render(const RenderRequest& request);
  Prepared& prepare(Prepared& slot, const nlohmann::json& scene, Backend backend);
  void send_frame(std::int64_t seq, nlohmann::json header, const std::vector<std::byte>& image);

  DatasetCatalog& catalog_;
  WorkerOutput output_;
  int threads_;
  Backend backend_;

  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<ClientMessage> pending_;
  bool stop_ = false;
  Cancellation cancel_;  // the request in flight's: its table build and its render

  // The worker thread's own state; the account first, as it must outlive what is charged to it.
  MemoryAccount account_;
  std::shared_ptr<const Dataset> dataset_;
  Prepared method_, exact_;
  std::optional<Rendered> final_, reference_;
  int preview_scale_ = 2;

  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace vri::viewer
