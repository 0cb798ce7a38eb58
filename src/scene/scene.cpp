#include "vri/scene.hpp"

#include <algorithm>
#include <utility>
#include <variant>

#include "vri/error.hpp"

namespace vri {

const GridVolume& Scene::grid() const {
  if (const auto* g = std::get_if<GridVolume>(&volume)) return *g;
  throw Error("this scene's volume is a tetrahedral mesh, not a regular grid");
}

const TetMesh& Scene::mesh() const {
  if (const auto* m = std::get_if<TetMesh>(&volume)) return *m;
  throw Error("this scene's volume is a regular grid, not a tetrahedral mesh");
}

const ClipRegion& Scene::clip() const {
  return std::visit([](const auto& v) -> const ClipRegion& { return v.clip_region(); }, volume);
}

void set_clip(Volume& volume, ClipRegion clip) {
  std::visit([&](auto& v) { v.set_clip(std::move(clip)); }, volume);
}

Histogram histogram(const Volume& volume, int bins) {
  if (const auto* g = std::get_if<GridVolume>(&volume)) return histogram(*g, bins);
  return histogram(std::span<const float>(std::get<TetMesh>(volume).scalars()), bins);
}

std::pair<Vec3, Vec3> bounds(const Volume& volume) {
  if (const auto* g = std::get_if<GridVolume>(&volume)) return {g->whole_lo(), g->whole_hi()};  // a part's whole grid
  const std::vector<Vec3>& points = std::get<TetMesh>(volume).points();
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  return {lo, hi};
}

}  // namespace vri
