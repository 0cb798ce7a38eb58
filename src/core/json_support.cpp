#include "core/json_support.hpp"

#include <algorithm>
#include <vector>

#include "vri/error.hpp"

namespace vri {

namespace {

// Levenshtein distance.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t k = 0; k <= b.size(); ++k) row[k] = k;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t k = 1; k <= b.size(); ++k) {
      const std::size_t up = row[k];
      row[k] = std::min({row[k] + 1, row[k - 1] + 1, diag + (a[i - 1] != b[k - 1])});
      diag = up;
    }
  }
  return row[b.size()];
}

}  // namespace

int json_depth(std::string_view text, int limit) {
  int depth = 0, deepest = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size() && deepest <= limit; ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') ++i;  // the escaped character cannot end the string
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  if (json_depth(text) > kMaxJsonDepth)
    throw Error(source + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number like 1E99999
    std::string what = e.what();
    if (auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw Error(source + ": malformed JSON: " + printable(what, 200));
  }
}

std::string found(const nlohmann::json& v) {
  return printable(v.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), 40);
}

std::string number_text(double v) {
  std::string t = std::to_string(v);
  if (t.find('.') != std::string::npos) {
    t.erase(t.find_last_not_of('0') + 1);
    if (t.back() == '.') t.pop_back();
  }
  return t;
}

std::string key_suggestion(std::string_view key, std::span<const std::string_view> known) {
  std::string_view best;
  std::size_t best_d = std::string::npos;
  for (std::string_view k : known)
    if (const std::size_t d = edit_distance(key, k); d < best_d) best = k, best_d = d;
  if (best_d <= std::max<std::size_t>(2, best.size() / 3)) return " (did you mean '" + std::string(best) + "'?)";
  std::string msg = " (known:";
  for (std::string_view k : known) (msg += ' ') += k;
  return msg + ")";
}

}  // namespace vri
