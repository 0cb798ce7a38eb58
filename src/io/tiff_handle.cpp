// libtiff behind vri::Error (tiff_handle.hpp).
#include "tiff_handle.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>

#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/io.hpp"

namespace vri::tiff {

namespace {

// Where messages libtiff reports without a TIFF* (or before one exists) go:
// the innermost open Handle of this thread.
thread_local Handle::State* current = nullptr;

void keep(Handle::State* state, const char* module, const char* fmt, va_list ap) {
  if (!state) return;
  char text[512];
  std::vsnprintf(text, sizeof text, fmt, ap);
  std::string message = text;
  // The module is often the file's name, which the error names already.
  if (module && *module && state->name != module) message = std::string(module) + ": " + message;
  state->error = printable(message, 200);
}

int error_handler(TIFF*, void* user, const char* module, const char* fmt, va_list ap) {
  keep(static_cast<Handle::State*>(user), module, fmt, ap);
  return 1;  // handled: libtiff's global handler (stderr) is not called
}

// Warnings are dropped, but libtiff's "Bogus StripByteCounts field,
// ignoring and calculating from imagelength" (or TileByteCounts) is noted.
int warning_handler(TIFF*, void* user, const char*, const char* fmt, va_list ap) {
  char text[512];
  std::vsnprintf(text, sizeof text, fmt, ap);
  const std::string message = text;
  if (user && message.find("ByteCounts") != std::string::npos &&
      (message.find("Bogus") != std::string::npos || message.find("ignoring") != std::string::npos))
    static_cast<Handle::State*>(user)->counts_replaced = true;
  return 1;
}

void global_error_handler(const char* module, const char* fmt, va_list ap) { keep(current, module, fmt, ap); }

// Installed once for the process: libtiff never prints to stderr.
void install_global_handlers() {
  static const bool installed = [] {
    TIFFSetErrorHandler(global_error_handler);
    TIFFSetWarningHandler(nullptr);
    return true;
  }();
  (void)installed;
}

tmsize_t mem_read(thandle_t h, void* buf, tmsize_t size) {
  auto& s = *static_cast<Handle::State*>(h);
  if (size <= 0 || s.pos >= s.bytes.size()) return 0;
  const std::uint64_t n = std::min<std::uint64_t>(std::uint64_t(size), s.bytes.size() - s.pos);
  std::memcpy(buf, s.bytes.data() + s.pos, n);
  s.pos += n;
  return tmsize_t(n);
}

tmsize_t mem_write(thandle_t, void*, tmsize_t) { return -1; }

toff_t mem_seek(thandle_t h, toff_t offset, int whence) {
  auto& s = *static_cast<Handle::State*>(h);
  const std::uint64_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? s.pos : s.bytes.size();
  // toff_t is unsigned: a negative move arrives as a huge value that wraps.
  const std::uint64_t to = base + std::uint64_t(offset);
  if (whence != SEEK_SET && std::int64_t(offset) < 0 && std::uint64_t(-std::int64_t(offset)) > base)
    return toff_t(-1);
  s.pos = to;
  return to;
}

int mem_close(thandle_t) { return 0; }
toff_t mem_size(thandle_t h) { return static_cast<Handle::State*>(h)->bytes.size(); }
int mem_map(thandle_t, void**, toff_t*) { return 0; }  // not mapped: read through mem_read
void mem_unmap(thandle_t, void*, toff_t) {}

// Options of every open: the handlers above and libtiff's allocations capped
// by the memory budget.
struct Options {
  TIFFOpenOptions* opts = TIFFOpenOptionsAlloc();
  explicit Options(Handle::State* state) {
    if (!opts) throw Error("libtiff could not allocate its options");
    const std::uint64_t cap = std::min<std::uint64_t>(memory_limit(), std::uint64_t(std::numeric_limits<tmsize_t>::max()));
    TIFFOpenOptionsSetMaxSingleMemAlloc(opts, tmsize_t(cap));
    TIFFOpenOptionsSetErrorHandlerExtR(opts, error_handler, state);
    TIFFOpenOptionsSetWarningHandlerExtR(opts, warning_handler, state);
  }
  ~Options() { TIFFOpenOptionsFree(opts); }
  Options(const Options&) = delete;
  Options& operator=(const Options&) = delete;
};

}  // namespace

Handle::Handle(const std::filesystem::path& path, const std::string& where) : state_(std::make_unique<State>()) {
  install_global_handlers();
  // The operating system's refusals (missing, a folder, no permission) as
  // every reader reports them.
  checked_file_size(path);
  if (!std::ifstream(path, std::ios::binary))
    throw FileError("cannot open '" + path.string() + "': " + std::strerror(errno));
  state_->name = path.string();
  const Options options(state_.get());
  state_->previous = current;
  current = state_.get();
  // "m": no memory mapping (a file cut short while mapped would be a SIGBUS).
  opened(TIFFOpenExt(path.c_str(), "rm", options.opts), where);
}

Handle::Handle(std::span<const std::byte> bytes, const std::string& source, const std::string& where)
    : state_(std::make_unique<State>()) {
  install_global_handlers();
  state_->name = source;
  state_->bytes = bytes;
  const Options options(state_.get());
  state_->previous = current;
  current = state_.get();
  opened(TIFFClientOpenExt(source.c_str(), "rm", state_.get(), mem_read, mem_write, mem_seek, mem_close, mem_size,
                           mem_map, mem_unmap, options.opts),
         where);
}

void Handle::opened(TIFF* tif, const std::string& where) {
  if (tif) {
    tif_ = tif;
    return;
  }
  current = state_->previous;
  throw Error(where + ": " + (state_->error.empty() ? std::string("libtiff cannot open it") : state_->error));
}

Handle::~Handle() {
  TIFFClose(tif_);
  current = state_->previous;
}

void Handle::fail(const std::string& context, const std::string& what) const {
  throw Error(context + ": " + what + (state_->error.empty() ? "" : ": " + state_->error));
}

}  // namespace vri::tiff
