#pragma once
// A progress line on stderr for long renders (issue 20, item 5): shown only
// when stderr is a terminal, only once the render has taken a second, and
// never with --quiet, so scripts and logs see nothing of it.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <mutex>

namespace vri::cli {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled) : enabled_(enabled && ::isatty(STDERR_FILENO)) {}
  ~ProgressBar() { finish(); }
  // Clears the line, so the summary that follows starts on a clean one.
  void finish() {
    std::lock_guard lock(mutex_);
    if (shown_) std::fputs("\r\033[K", stderr);
    shown_ = false;
    enabled_ = false;
  }
  // For RenderOptions::progress: called from render threads.
  void operator()(double fraction) {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    if (std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
    const int percent = int(fraction * 100);
    const int filled = percent * 30 / 100;
    std::fprintf(stderr, "\rvri: rendering [%.*s%*s] %3d%%", filled, "##############################", 30 - filled,
                 "", percent);
    std::fflush(stderr);
    shown_ = true;
  }

 private:
  bool enabled_;
  bool shown_ = false;
  std::mutex mutex_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace vri::cli
