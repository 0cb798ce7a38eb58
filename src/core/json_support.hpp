#pragma once
// Helpers every JSON reader of vri shares (the scene loader, the
// transfer-function forms, ParaView colour maps), so their messages read alike.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace vri {

// The deepest nesting of arrays and objects any reader of vri accepts. Scenes
// and messages nest 5 or 6 deep; past a few thousand levels the JSON
// library's recursive walks (dump, comparisons, the viewer's checks)
// overflow the stack (issue 47).
inline constexpr int kMaxJsonDepth = 100;

// The nesting depth of the arrays and objects in `text` (brackets outside
// strings), stopping early once it passes `limit`: linear, no recursion, so
// it can vet text before any parse.
int json_depth(std::string_view text, int limit = kMaxJsonDepth);

// The JSON of `text`; vri::Error "SOURCE: malformed JSON: ..." (nlohmann's
// message without its byte-offset prefix) if it is not, or "SOURCE: JSON
// nested deeper than 100 levels" before parsing.
nlohmann::json parse_json(std::string_view text, const std::string& source);


// A JSON value as the user wrote it, escaped and short, for "found ...".
std::string found(const nlohmann::json& v);

// A number for messages: std::to_string without trailing zeros ("0.5", "12").
std::string number_text(double v);

// What an "unknown key" message adds: " (did you mean 'k'?)" for the nearest
// known key when it is close (a typo), else " (known: a b c)".
std::string key_suggestion(std::string_view key, std::span<const std::string_view> known);

}  // namespace vri
