#pragma once
// CylindricalTable: the (l, s_f, s_b) table resampled on "cylinder" planes
// (Roettger & Ertl 2002, Sec. 4). In normalised coordinates (s_f, s_b, l in
// [0, 1]) every pixel of one projected tetrahedron lies on the plane through
// the front diagonal (s_f = s_b, l = 0) and the thick vertex's (s_f, s_b, l).
// Sheared so that the diagonal is an axis, these planes are indexed by an
// angle alpha in [0, 1] (0 to 180 degrees); each is projected onto the nearest
// of the alpha = 0, 90, 180 degree planes, giving equally sized square 2D
// tables over (s, t). Their equation 9, for plane alpha and (s, t) in [0,1]^2:
//   alpha in [0, .25]:  (s_f, s_b, l) = (t + s, t, 4 alpha s)
//   alpha in [.25, .5]: (t + 4 (.5 - alpha) s, t, s)
//   alpha in [.5, .75]: (t - 4 (alpha - .5) s, t, s)
//   alpha in [.75, 1]:  (t - s, t, 4 (1 - alpha) s)
// and its inverse, equation 10, gives the thick vertex's alpha (alpha()).
// Lookups interpolate bilinearly in the two planes nearest alpha and linearly
// between them. All planes are tiles of one array, as in the paper's Fig. 10.
#include <vector>

#include "vri/geometry.hpp"
#include "tables/slab_table.hpp"

namespace vri {

class CylindricalTable {
 public:
  // Resamples `table` (over its axis and lengths up to table.max_length())
  // on `planes` >= 2 planes of size x size.
  CylindricalTable(const SlabTable& table, int size, int planes);

  // Equation 10: the plane through the diagonal and (l, s_f, s_b), in [0, 1].
  double alpha(double l, double s_f, double s_b) const;
  // The segment (l, s_f, s_b) read from the planes next to `alpha`, after
  // projecting it onto alpha's nearest axis plane (exact when the segment
  // lies on plane alpha).
  Rgba lookup(double alpha, double l, double s_f, double s_b) const;
  double max_length() const { return max_length_; }
  int planes() const { return planes_; }

 private:
  int n_, planes_;
  double s_lo_, s_span_, max_length_;
  std::vector<float> tiles_;  // [plane][s][t][rgba]
};

// pt-cylindrical's interpolated lighting: the weighted (l, s_f, s_b) tables
// (weighted_tables.hpp, packed front/back) resampled on the same planes. The
// resampling is linear, so front + back is still the resampled plain table.
struct WeightedCylindricalTables {
  CylindricalTable front, back;
};

}  // namespace vri
