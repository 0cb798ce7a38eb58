#pragma once
// Walks a ray through the cells of a grid (Amanatides & Woo style), giving the
// piece of the ray inside each cell. Inside one cell the trilinear field along
// the ray is a cubic in t, which is what exact integration relies on.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "vri/geometry.hpp"
#include "vri/volume.hpp"

namespace vri {

struct CellSegment {
  std::array<int, 3> cell;  // lower corner (i, j, k)
  double ta, tb;            // world-distance range along the ray
  Vec3 local0;              // cell-local coordinates at ta (in [0,1]^3 up to rounding)
  Vec3 local_dir;           // d(local)/dt
};

// One axis of the cell walk from t0: the ray's grid position at t = 0 and per
// unit t, its direction (-1, 0 or 1), the first face plane ahead and where
// the ray crosses it (infinity when it does not move along the axis). Planes
// are crossed at (plane - u0) / du, recomputed from the integer plane (no
// accumulated drift). Shared with preint2-dual's packets, whose lanes walk as
// this walk does.
struct CellWalkAxis {
  double u0, du, plane, t_next;
  int dir;
};
inline CellWalkAxis cell_walk_axis(const GridVolume& vol, const Ray& ray, double t0, int a) {
  CellWalkAxis w;
  w.u0 = (ray.origin[a] - vol.origin()[a]) / vol.spacing()[a];
  w.du = ray.dir[a] / vol.spacing()[a];
  const double ua = w.u0 + w.du * t0;
  w.dir = w.du > 0 ? 1 : (w.du < 0 ? -1 : 0);
  w.plane = w.dir > 0 ? std::floor(ua) + 1 : std::ceil(ua) - 1;
  w.t_next = w.dir ? (w.plane - w.u0) / w.du : std::numeric_limits<double>::infinity();
  return w;
}

// Calls visit(const CellSegment&) for every cell piece of [iv.t0, iv.t1], front
// to back; stops early when visit returns false. Plane crossings are recomputed
// from their integer index (no accumulated drift), and each piece's cell is
// taken at its midpoint and clamped, so rays along faces or the box edge work.
template <class Visit>
void for_each_cell_segment(const GridVolume& vol, const Ray& ray, Interval iv, Visit&& visit) {
  const auto& n = vol.dims();
  double u0[3], du[3], t_next[3], plane[3];
  int dir[3];
  for (int a = 0; a < 3; ++a) {
    const CellWalkAxis w = cell_walk_axis(vol, ray, iv.t0, a);
    u0[a] = w.u0, du[a] = w.du, plane[a] = w.plane, t_next[a] = w.t_next, dir[a] = w.dir;
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
