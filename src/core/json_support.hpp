#pragma once
// Helpers every JSON reader of vri shares (the scene loader, the
// transfer-function forms, ParaView colour maps), so their messages read alike.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace vri {

// The JSON of `text`; vri::Error "SOURCE: malformed JSON: ..." (nlohmann's
// message without its byte-offset prefix) if it is not.
nlohmann::json parse_json(std::string_view text, const std::string& source);

// A file's bytes as text (vri::FileError if it cannot be read).
std::string text_of(const std::filesystem::path& path);

// A JSON value as the user wrote it, escaped and short, for "found ...".
std::string found(const nlohmann::json& v);

// A number for messages: std::to_string without trailing zeros ("0.5", "12").
std::string number_text(double v);

// What an "unknown key" message adds: " (did you mean 'k'?)" for the nearest
// known key when it is close (a typo), else " (known: a b c)".
std::string key_suggestion(std::string_view key, std::span<const std::string_view> known);

}  // namespace vri
