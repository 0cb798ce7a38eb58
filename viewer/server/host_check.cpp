#include "host_check.hpp"

#include <unistd.h>

#include <algorithm>
#include <boost/asio/ip/address.hpp>
#include <cctype>

namespace vri::viewer {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return out;
}

bool is_ip(const std::string& name) {
  boost::system::error_code ec;
  boost::asio::ip::make_address(name, ec);
  return !ec;
}

}  // namespace

std::string host_name_of(std::string_view header) {
  if (header.empty()) return {};
  if (header.front() == '[') {  // [v6]:port
    const auto close = header.find(']');
    if (close == std::string_view::npos) return {};
    const std::string_view rest = header.substr(close + 1);
    if (!rest.empty() && rest.front() != ':') return {};
    return std::string(header.substr(1, close - 1));
  }
  const auto colon = header.find(':');
  if (colon != std::string_view::npos && header.find(':', colon + 1) != std::string_view::npos) return {};
  return std::string(header.substr(0, colon));
}

bool allowed_host(std::string_view header, const std::string& bound) {
  const std::string name = lower(host_name_of(header));
  if (name.empty()) return false;
  if (is_ip(name) || name == "localhost" || name == lower(bound)) return true;
  char machine[256] = {};
  return ::gethostname(machine, sizeof machine - 1) == 0 && name == lower(machine);
}

}  // namespace vri::viewer
