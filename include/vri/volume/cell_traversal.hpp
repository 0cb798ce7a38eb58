#pragma once
// Walks a ray through the cells of a grid (Amanatides & Woo style), giving the
// piece of the ray inside each cell. Inside one cell the trilinear field along
// the ray is a cubic in t, which is what exact integration relies on.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "vri/core/ray.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

struct CellSegment {
  std::array<int, 3> cell;  // lower corner (i, j, k)
  double ta, tb;            // world-distance range along the ray
  Vec3 local0;              // cell-local coordinates at ta (in [0,1]^3 up to rounding)
  Vec3 local_dir;           // d(local)/dt
};

// Calls visit(const CellSegment&) for every cell piece of [iv.t0, iv.t1], front
// to back; stops early when visit returns false. Plane crossings are recomputed
// from their integer index (no accumulated drift), and each piece's cell is
// taken at its midpoint and clamped, so rays along faces or the box edge work.
template <class Visit>
void for_each_cell_segment(const GridVolume& vol, const Ray& ray, Interval iv, Visit&& visit) {
  const auto& n = vol.dims();
  const Vec3 sp = vol.spacing(), org = vol.origin();
  constexpr double inf = std::numeric_limits<double>::infinity();
  double u0[3], du[3], t_next[3], plane[3];
  int dir[3];
  for (int a = 0; a < 3; ++a) {
    u0[a] = (ray.origin[a] - org[a]) / sp[a];
    du[a] = ray.dir[a] / sp[a];
    const double ua = u0[a] + du[a] * iv.t0;
    dir[a] = du[a] > 0 ? 1 : (du[a] < 0 ? -1 : 0);
    plane[a] = dir[a] > 0 ? std::floor(ua) + 1 : std::ceil(ua) - 1;
    t_next[a] = dir[a] ? (plane[a] - u0[a]) / du[a] : inf;
  }
  double ta = iv.t0;
  while (ta < iv.t1) {
    const double tb = std::min({t_next[0], t_next[1], t_next[2], iv.t1});
    for (int a = 0; a < 3; ++a)
      while (dir[a] && t_next[a] <= tb) {
        plane[a] += dir[a];
        t_next[a] = (plane[a] - u0[a]) / du[a];
      }
    if (tb > ta) {
      CellSegment seg;
      seg.ta = ta;
      seg.tb = tb;
      const double tm = 0.5 * (ta + tb);
      for (int a = 0; a < 3; ++a) {
        const double um = std::floor(u0[a] + du[a] * tm);
        seg.cell[a] = static_cast<int>(std::clamp(um, 0.0, double(n[a] - 2)));
        seg.local0[a] = u0[a] + du[a] * ta - seg.cell[a];
        seg.local_dir[a] = du[a];
      }
      if (!visit(static_cast<const CellSegment&>(seg))) return;
    }
    ta = tb;
  }
}

}  // namespace vri
