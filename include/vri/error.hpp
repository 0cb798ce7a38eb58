#pragma once
// vri/error.hpp: the exceptions vri throws: Error for bad input, FileError, Cancelled; printable() for quoting input in a message.

#include <stdexcept>
#include <string>
#include <string_view>

// ---- error -----------------------------------------------------------------
// vri::Error: the one exception type for bad input. Its message is a single
// line meant for the user ("cannot read 'x.raw': file is 12 bytes, expected 64").

namespace vri {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// A file that cannot be opened, read or written (the operating system said
// no: missing, a directory, no permission, short). Python raises it as OSError.
class FileError : public Error {
 public:
  using Error::Error;
};

}  // namespace vri

// ---- printable -------------------------------------------------------------
// Text from untrusted input made safe for a one-line error message.

namespace vri {

// Control bytes and bytes that are not valid UTF-8 as \xNN;
// cut to `max_bytes` with "..." so one message stays one short line.
std::string printable(std::string_view text, std::size_t max_bytes = 80);

// An error message as it leaves vri (the CLI's stderr, the viewer's error
// replies, Python's exceptions): printable() at kMaxMessageBytes, so text a
// reader quoted from a file without care (an escape sequence, a newline, a
// 50 MB header line) still makes one short line (issue 47).
inline constexpr std::size_t kMaxMessageBytes = 1000;
inline std::string message_line(std::string_view message) { return printable(message, kMaxMessageBytes); }

// A number as %g (1e-07, not 0.000000).
std::string format_g(double value);

}  // namespace vri

// ---- cancelled -------------------------------------------------------------
// RenderCancelled: work stopped from another thread (vri/render.hpp):
// a render between its tiles, a table build between its rows.

namespace vri {

class RenderCancelled : public Error {
 public:
  RenderCancelled() : Error("the render was cancelled") {}
};

// In work a Cancellation runs: throws RenderCancelled once it is cancelled.
// The table builders call it after their parallel loops, which a cancel cuts
// short: what they leave half built is then never used, converted or copied.
void throw_if_build_cancelled();

}  // namespace vri
