#pragma once
// Files compiled into the binary (viewer/embed_files.cmake): the page's HTML,
// scripts and style sheet, and the bundled transfer-function presets, so the
// viewer needs nothing at run time but the volumes it shows.
#include <cstddef>
#include <span>
#include <string_view>

namespace vri::viewer {

struct EmbeddedFile {
  std::string_view name;  // e.g. "index.html", "bonsai.json"
  std::string_view content;
};

std::span<const EmbeddedFile> web_files();
std::span<const EmbeddedFile> preset_files();

// The content type of a file by its extension ("text/html; charset=utf-8", ...).
std::string_view content_type(std::string_view name);

}  // namespace vri::viewer
