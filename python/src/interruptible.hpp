#pragma once
// interruptible(work): runs work(cancellation) with the GIL released on a
// thread of its own while the calling thread checks for signals every 0.1 s
// (PyErr_CheckSignals). On one - Ctrl-C, Jupyter's "interrupt kernel" - the
// work is cancelled (a render between tiles, a table build between rows:
// vri/render.hpp) and, once it has stopped, the signal's
// exception (KeyboardInterrupt) is raised. Issue 47: a render could not be
// interrupted until it ended.
#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>

#include "bindings.hpp"
#include "vri/render.hpp"

namespace vri::python {

template <class F>
std::invoke_result_t<F&, const Cancellation&> interruptible(F&& work) {
  using Result = std::invoke_result_t<F&, const Cancellation&>;
  Cancellation cancellation;
  std::optional<Result> result;
  std::exception_ptr error;
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false, interrupted = false;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        cancellation.run([&] { result.emplace(work(cancellation)); });
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
    for (;;) {
      {
        std::unique_lock lock(mutex);
        if (finished.wait_for(lock, std::chrono::milliseconds(100), [&] { return done; })) break;
      }
      if (interrupted) continue;
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {  // a handler raised: its exception is set
        interrupted = true;
        cancellation.cancel();
      }
    }
    worker.join();
  }
  if (interrupted) throw py::error_already_set();
  if (error) std::rethrow_exception(error);
  return std::move(*result);
}

}  // namespace vri::python
