#pragma once
// Text from untrusted input made safe for a one-line error message.
#include <string>
#include <string_view>

namespace vri {

// Control bytes and bytes that are not valid UTF-8 as \xNN;
// cut to `max_bytes` with "..." so one message stays one short line.
std::string printable(std::string_view text, std::size_t max_bytes = 80);

// A number as %g (1e-07, not 0.000000).
std::string format_g(double value);

}  // namespace vri
