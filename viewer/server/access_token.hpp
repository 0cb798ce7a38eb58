#pragma once
// The viewer's access token: 128 random bits that every HTTP request and the
// WebSocket handshake must carry (the `token` query parameter, or the cookie
// the page's first load sets), as Jupyter does.
#include <string>
#include <string_view>

namespace vri::viewer {

inline constexpr std::string_view kTokenCookie = "vri_token";

// 32 hex digits from std::random_device.
std::string make_token();

// The token a request carries: `token=` in the target's query, else the
// cookie in the Cookie header; empty if neither.
std::string token_of(std::string_view target, std::string_view cookie_header);

// Compares in time independent of where the strings differ.
bool same_token(std::string_view given, std::string_view expected);

// The target's path without the query ("/ws?token=x" -> "/ws").
std::string_view path_of(std::string_view target);

}  // namespace vri::viewer
