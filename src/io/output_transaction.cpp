#include "vri/io.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cerrno>
#include <cstring>
#include <string>

#include "vri/error.hpp"

namespace vri {

namespace fs = std::filesystem;

namespace {

// Temporaries a signal handler may unlink: fixed slots, so the handler needs
// no allocation or lock (only async-signal-safe calls, POSIX.1-2008 §2.4.3).
constexpr int kSlots = 64;
constexpr std::size_t kPathMax = 4096;
struct Slot {
  std::atomic<bool> used{false};
  char path[kPathMax];
};
Slot g_slots[kSlots];
std::atomic<OutputTransaction*> g_active{nullptr};

int register_temp(const std::string& path) {
  if (path.size() >= kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    if (g_slots[i].used.load(std::memory_order_acquire)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].used.store(true, std::memory_order_release);
    return i;
  }
  return -1;
}

void unregister_temp(const fs::path& path) {
  for (Slot& s : g_slots)
    if (s.used.load(std::memory_order_acquire) && path.string() == s.path)
      s.used.store(false, std::memory_order_release);
}

extern "C" void unlink_temporaries_and_reraise(int sig) {
  for (Slot& s : g_slots)
    if (s.used.load(std::memory_order_acquire)) ::unlink(s.path);
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

// Signals that would kill the process while a temporary is created are held
// back on this thread for that moment. Another thread (a TBB worker) may still
// take the signal, so each name is registered before the file exists: the
// handler then unlinks a file that is not there yet, never misses one.
class BlockTermination {
 public:
  BlockTermination() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, &old_);
  }
  ~BlockTermination() { pthread_sigmask(SIG_SETMASK, &old_, nullptr); }

 private:
  sigset_t old_;
};

[[noreturn]] void fail(const fs::path& target, const std::string& why) {
  throw FileError("cannot write '" + target.string() + "': " + why);
}

// An existing target must be a regular file or a link (a link is replaced,
// never followed): as root, rename() would put a CSV where /dev/null was
// (issue 47). Checked when staging and again just before the rename.
void refuse_special(const fs::path& target) {
  struct stat st {};
  if (::lstat(target.c_str(), &st) != 0) return;  // nothing there yet
  if (S_ISDIR(st.st_mode)) fail(target, "is a directory");
  if (!S_ISREG(st.st_mode) && !S_ISLNK(st.st_mode))
    fail(target, "is not a regular file (a device, FIFO or socket is never replaced)");
}

}  // namespace

OutputTransaction::OutputTransaction() : previous_(g_active.exchange(this)) {}

OutputTransaction::~OutputTransaction() {
  discard();
  g_active.store(previous_);
}

OutputTransaction* OutputTransaction::active() { return g_active.load(); }

void OutputTransaction::stage(const fs::path& target, std::span<const std::byte> bytes) {
  stage(target, std::span(&bytes, 1));
}

void OutputTransaction::stage(const fs::path& target, std::span<const std::span<const std::byte>> parts) {
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) fail(target, "directory '" + dir.string() + "' does not exist");
  if (target.filename().empty() || fs::is_directory(target, ec)) fail(target, "is a directory");
  refuse_special(target);
  // O_EXCL: a name that exists already (a planted link included) is never
  // opened; another name is tried instead.
  fs::path temp;
  int fd = -1;
  {
    const BlockTermination hold;
    for (int k = 0; k < 100 && fd < 0; ++k) {
      // Appended piecewise: GCC 12's -Wrestrict misfires on "." + string.
      std::string name = ".";
      name += target.filename().string();
      name += ".tmp" + std::to_string(::getpid()) + "." + std::to_string(k);
      temp = dir / name;
      if (register_temp(temp.string()) < 0) fail(target, "too many outputs");
      fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
      if (fd >= 0) break;
      const int why = errno;
      unregister_temp(temp);  // not ours: the handler must leave it alone
      if (why != EEXIST) fail(target, std::strerror(why));
    }
    if (fd < 0) fail(target, "no free temporary name beside it");
    staged_.push_back({temp, target});
  }
  for (const auto bytes : parts) {
    const char* p = reinterpret_cast<const char*>(bytes.data());
    std::size_t left = bytes.size();
    while (left > 0) {
      const ssize_t n = ::write(fd, p, left);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        const std::string why = n < 0 ? std::strerror(errno) : "write failed";
        ::close(fd);
        fail(target, why);  // the destructor removes the temporary
      }
      p += n;
      left -= std::size_t(n);
    }
  }
  if (::close(fd) != 0) fail(target, std::strerror(errno));
}

void OutputTransaction::create_directories(const fs::path& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec) fail(dir, ec.message());
  created_.insert(created_.end(), missing.begin(), missing.end());  // deepest first
}

void OutputTransaction::commit() {
  while (!staged_.empty()) {
    const Staged s = staged_.front();
    // rename() replaces a link at the target; it never writes through it.
    refuse_special(s.target);
    if (::rename(s.temp.c_str(), s.target.c_str()) != 0) fail(s.target, std::strerror(errno));
    unregister_temp(s.temp);
    staged_.erase(staged_.begin());
  }
  created_.clear();  // they hold the outputs now
}

void OutputTransaction::discard() noexcept {
  for (const Staged& s : staged_) {
    ::unlink(s.temp.c_str());
    unregister_temp(s.temp);
  }
  staged_.clear();
  for (const fs::path& dir : created_) ::rmdir(dir.c_str());  // only if empty
  created_.clear();
}

void remove_temporaries_on_signal() {
  struct sigaction sa {};
  sa.sa_handler = unlink_temporaries_and_reraise;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace vri
