#include "vri/transfer_function.hpp"

#include <algorithm>
#include <cctype>

#include "transfer/colormap_data.hpp"

namespace vri {

std::array<double, 3> Colormap::at(double x) const {
  const auto& p = points;
  if (!(x > p.front().x)) return {p.front().r, p.front().g, p.front().b};  // NaN too
  if (x >= p.back().x) return {p.back().r, p.back().g, p.back().b};
  const auto hi = std::upper_bound(p.begin(), p.end(), x, [](double v, const ColormapPoint& q) { return v < q.x; });
  const ColormapPoint& a = hi[-1];
  const ColormapPoint& b = *hi;
  const double t = (x - a.x) / (b.x - a.x);
  return {a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b)};
}

const Colormap* find_colormap(std::string_view name) {
  std::string key;
  for (const char c : name) key += (c == ' ' || c == '-') ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
  for (const Colormap& m : detail::kColormaps)
    if (m.name == key) return &m;
  return nullptr;
}

std::vector<std::string> colormap_names() {
  std::vector<std::string> names;
  for (const Colormap& m : detail::kColormaps) names.emplace_back(m.name);
  return names;
}

}  // namespace vri
