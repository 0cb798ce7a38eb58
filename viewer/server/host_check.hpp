#pragma once
// The Host header a request may carry (against DNS rebinding: a page of
// another site whose name is made to resolve to this machine then sends the
// site's name, which is refused). Allowed: an IP address, "localhost", this
// machine's name (gethostname), and the --host given; any port (an SSH tunnel
// may forward another). The viewer's token still guards every request.
#include <string>
#include <string_view>

namespace vri::viewer {

// The name part of a Host header: "a.b:80" -> "a.b", "[::1]:80" -> "::1";
// empty when it is malformed.
std::string host_name_of(std::string_view header);

// Whether a request with this Host header is answered; `bound` is --host.
bool allowed_host(std::string_view header, const std::string& bound);

}  // namespace vri::viewer
