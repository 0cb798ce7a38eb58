#include "cell_cubics.hpp"

#include "core/f64x4.hpp"
#include "core/simd.hpp"

namespace vri {

// trilinear_along (cubic.cpp) lane by lane, each expression in its order.
VRI_AVX2_CLONES void CellCubics::run_lanes() {
  using namespace f64x4;
  const V c000 = load(corner[0]), c100 = load(corner[1]), c010 = load(corner[2]), c110 = load(corner[3]),
          c001 = load(corner[4]), c101 = load(corner[5]), c011 = load(corner[6]), c111 = load(corner[7]);
  const V a = c000, bx = c100 - c000, by = c010 - c000, bz = c001 - c000;
  const V exy = c110 - c100 - c010 + c000;
  const V exz = c101 - c100 - c001 + c000;
  const V eyz = c011 - c010 - c001 + c000;
  const V hxyz = c111 - c110 - c101 - c011 + c100 + c010 + c001 - c000;
  const V x0 = load(local0[0]), y0 = load(local0[1]), z0 = load(local0[2]);
  const double p = dir[0], q = dir[1], r = dir[2];
  const V xy0 = x0 * y0, xy1 = x0 * q + y0 * p;
  const double xy2 = p * q;
  const V xz0 = x0 * z0, xz1 = x0 * r + z0 * p;
  const double xz2 = p * r;
  const V yz0 = y0 * z0, yz1 = y0 * r + z0 * q;
  const double yz2 = q * r;
  const V xyz0 = xy0 * z0, xyz1 = xy0 * r + xy1 * z0, xyz2 = xy1 * r + xy2 * z0;
  const double xyz3 = xy2 * r;
  store(c[0], a + bx * x0 + by * y0 + bz * z0 + exy * xy0 + exz * xz0 + eyz * yz0 + hxyz * xyz0);
  store(c[1], bx * p + by * q + bz * r + exy * xy1 + exz * xz1 + eyz * yz1 + hxyz * xyz1);
  store(c[2], exy * xy2 + exz * xz2 + eyz * yz2 + hxyz * xyz2);
  store(c[3], hxyz * xyz3);
  V l = c000, h = c000;
  for (const V v : {c100, c010, c110, c001, c101, c011, c111}) l = v < l ? v : l, h = v > h ? v : h;
  store(lo, l);
  store(hi, h);
}

}  // namespace vri
