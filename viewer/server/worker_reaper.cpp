#include "worker_reaper.hpp"

namespace vri::viewer {

WorkerReaper::WorkerReaper() : thread_([this] { run(); }) {}

WorkerReaper::~WorkerReaper() { drain(); }

void WorkerReaper::retire(std::unique_ptr<RenderWorker> worker) {
  if (!worker) return;
  worker->request_stop();
  std::unique_lock lock(mutex_);
  if (draining_) {  // the server is stopping: nobody waits on this thread any more
    lock.unlock();
    worker.reset();
    return;
  }
  retired_.push_back(std::move(worker));
  wake_.notify_one();
}

void WorkerReaper::drain() {
  {
    std::lock_guard lock(mutex_);
    draining_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void WorkerReaper::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return draining_ || !retired_.empty(); });
    if (retired_.empty()) return;  // draining, nothing left
    std::unique_ptr<RenderWorker> worker = std::move(retired_.front());
    retired_.pop_front();
    lock.unlock();
    worker.reset();  // joins
    lock.lock();
  }
}

}  // namespace vri::viewer
