#pragma once
// One open TIFF for reading (src/io/tiff.cpp), through libtiff: a file
// (TIFFOpenExt, without memory mapping) or bytes in memory (TIFFClientOpenExt).
// libtiff's errors are captured, never printed, and become the text of the
// vri::Error that fail() throws; its warnings are dropped but one, about
// byte counts it replaced (byte_counts_replaced). The first Handle
// installs libtiff's process-wide handlers (errors reported without a TIFF*
// go to the innermost Handle of the thread, warnings nowhere), so libtiff
// never writes to stderr. libtiff's own allocations are capped by the memory
// budget (vri/memory.hpp).
#include <tiffio.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>

namespace vri::tiff {

class Handle {
 public:
  // `where` starts every error ("TIFF 'a.tif'"); vri::Error if libtiff
  // cannot open it (FileError if the file cannot be opened at all).
  Handle(const std::filesystem::path& path, const std::string& where);
  Handle(std::span<const std::byte> bytes, const std::string& source, const std::string& where);
  ~Handle();
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  TIFF* get() const { return tif_; }
  // Throws vri::Error "`context`: `what`: libtiff's last error" (without the
  // last part when libtiff said nothing).
  [[noreturn]] void fail(const std::string& context, const std::string& what) const;
  // Forgets libtiff's last error (before a call whose failure fail() reports).
  void clear_error() const { state_->error.clear(); }
  // Whether libtiff found the current directory's strip or tile byte counts
  // too short for its samples ("Bogus StripByteCounts") and replaced them by
  // an estimate, which reads on into whatever follows (issue 47). Reset by
  // each TIFFReadDirectory through next_directory().
  bool byte_counts_replaced() const { return state_->counts_replaced; }
  bool next_directory() const {
    state_->counts_replaced = false;
    return TIFFReadDirectory(tif_) != 0;
  }

  // State the libtiff callbacks reach through their user data.
  struct State {
    std::string error;                 // libtiff's last error message
    std::string name;                  // the name libtiff was given (left out of messages)
    std::span<const std::byte> bytes;  // in memory: the file
    std::uint64_t pos = 0;             // in memory: the read position
    State* previous = nullptr;         // the state errors without a TIFF* went to before
    bool counts_replaced = false;      // libtiff warned of bogus byte counts (byte_counts_replaced)
  };

 private:
  void opened(TIFF* tif, const std::string& where);

  std::unique_ptr<State> state_;
  TIFF* tif_ = nullptr;
};

}  // namespace vri::tiff
