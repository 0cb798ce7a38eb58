#pragma once
// Cancellation: work another thread may stop - a render between its tiles
// (flag(), for RenderOptions::cancel) and a table build between its rows
// (the TBB group run() puts it in: its parallel loops stop taking work, and
// the builders check tbb::is_current_task_group_canceling() per row). The
// viewer cancels a page's work when a newer request or its close comes;
// Python cancels a render on Ctrl-C.
#include <tbb/task_group.h>

#include <atomic>
#include <mutex>

#include "vri/render/renderer.hpp"

namespace vri {

class Cancellation {
 public:
  // From any thread: what runs stops soon, and what starts after does not run.
  void cancel() {
    std::lock_guard lock(mutex_);
    flag_ = true;
    if (group_) group_->cancel_group_execution();
  }
  // Before the next work, on the thread that runs it (ordered with cancel()
  // by the caller: the viewer takes its next request and resets under one lock).
  void reset() { flag_ = false; }
  bool cancelled() const { return flag_; }
  const std::atomic<bool>* flag() const { return &flag_; }

  // Runs f() in a TBB group that cancel() stops; throws RenderCancelled when it
  // was cancelled (what f left half built is the caller's to throw away, as
  // the exception unwinds it), else returns as f did.
  template <class F>
  void run(F&& f) {
    tbb::task_group_context context;
    {
      std::lock_guard lock(mutex_);
      if (flag_) throw RenderCancelled();
      group_ = &context;
    }
    tbb::task_group group(context);
    tbb::task_group_status status;
    try {
      status = group.run_and_wait([&] {
        // Off before the group resets its context: no cancel() reaches it after.
        struct Leave {
          Cancellation& c;
          ~Leave() {
            std::lock_guard lock(c.mutex_);
            c.group_ = nullptr;
          }
        } leave{*this};
        f();
      });
    } catch (...) {
      if (flag_) throw RenderCancelled();  // a failure of the cancelled work's leftovers
      throw;
    }
    if (status == tbb::task_group_status::canceled || flag_) throw RenderCancelled();
  }

 private:
  std::mutex mutex_;
  std::atomic<bool> flag_{false};
  tbb::task_group_context* group_ = nullptr;
};

}  // namespace vri
