#pragma once
// Text from untrusted input made safe for a one-line error message.
#include <string>
#include <string_view>

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
