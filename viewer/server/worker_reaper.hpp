#pragma once
// WorkerReaper: joins the render workers of pages that have gone, on a thread
// of its own. A worker may be deep in a table build when its page closes;
// joining it on the I/O thread froze every other page until it ended (issue
// 47). The worker is told to stop at once and joined here.
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>

#include "render_worker.hpp"

namespace vri::viewer {

class WorkerReaper {
 public:
  WorkerReaper();
  ~WorkerReaper();  // drain()
  WorkerReaper(const WorkerReaper&) = delete;
  WorkerReaper& operator=(const WorkerReaper&) = delete;

  // Cancels the worker's work and hands it over to be joined; returns at once.
  void retire(std::unique_ptr<RenderWorker> worker);
  // Joins every worker retired so far, and later ones on the caller's thread.
  void drain();

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<std::unique_ptr<RenderWorker>> retired_;
  bool draining_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

}  // namespace vri::viewer
