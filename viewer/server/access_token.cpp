#include "access_token.hpp"

#include <random>

namespace vri::viewer {

std::string make_token() {
  std::random_device device;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string token;
  for (int i = 0; i < 4; ++i) {
    const unsigned word = device();
    for (int k = 0; k < 8; ++k) token += kHex[(word >> (4 * k)) & 15];
  }
  return token;
}

std::string_view path_of(std::string_view target) { return target.substr(0, target.find('?')); }

namespace {

// The value of `key` in "a=1; key=2" (cookies, separator "; ") or "a=1&key=2" (queries, "&").
std::string value_in(std::string_view text, std::string_view key, char separator) {
  while (!text.empty()) {
    const std::size_t end = text.find(separator);
    std::string_view item = text.substr(0, end);
    while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
    if (item.size() > key.size() && item.substr(0, key.size()) == key && item[key.size()] == '=')
      return std::string(item.substr(key.size() + 1));
    if (end == std::string_view::npos) break;
    text.remove_prefix(end + 1);
  }
  return {};
}

}  // namespace

std::string token_of(std::string_view target, std::string_view cookie_header) {
  const std::size_t q = target.find('?');
  if (q != std::string_view::npos) {
    std::string t = value_in(target.substr(q + 1), "token", '&');
    if (!t.empty()) return t;
  }
  return value_in(cookie_header, kTokenCookie, ';');
}

bool same_token(std::string_view given, std::string_view expected) {
  if (given.size() != expected.size() || expected.empty()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < given.size(); ++i) diff |= static_cast<unsigned char>(given[i] ^ expected[i]);
  return diff == 0;
}

}  // namespace vri::viewer
