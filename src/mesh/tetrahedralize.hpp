#pragma once
// Splits every cell of a regular grid into tetrahedra over the same points, so
// one field can be rendered both as a grid and as a mesh. Face diagonals agree
// between neighbouring cells (the mesh is conforming):
//  - 5 per cell: a central tetrahedron and four corners; the mirror-image
//    pattern alternates with the parity of i+j+k, so every face diagonal joins
//    the two corners whose i+j+k is odd;
//  - 6 per cell: Kuhn's triangulation, all six around the diagonal (i,j,k) to
//    (i+1,j+1,k+1), the same in every cell.
// A field linear in space is reproduced exactly either way (trilinear and
// piecewise-linear interpolation agree on it).
#include "vri/volume.hpp"

namespace vri {

// tets_per_cell must be 5 or 6 (vri::Error otherwise).
TetMesh tetrahedralize(const GridVolume& grid, int tets_per_cell = 5);

}  // namespace vri
