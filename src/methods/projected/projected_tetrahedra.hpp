#pragma once
// Projected tetrahedra (SPEC §9 `pt`): Shirley & Tuchman (1990) with the
// pre-integrated (l, s_f, s_b) table of Roettger & Ertl (2002, Sec. 2-3).
// Each tetrahedron is projected and split (classify()) into 3 or 4 triangles
// around its thick vertex, which carries the front and back points of the
// longest ray through the tetrahedron, while the silhouette vertices carry
// front = back (l = 0). A software rasteriser interpolates, per pixel centre,
// the front and back points and scalars - perspective-correct: the weights of
// the screen-space barycentrics are divided by each vertex's view depth, the
// front and back triangles separately - so that l = |back - front|, s_f and
// s_b are those of the pixel's ray; then it looks them up in the table.
//
// Visibility: instead of a global cell order (MPVO and its non-convex
// heuristics), the fragments of each pixel are sorted by the view depth of
// their front point. Tetrahedra do not overlap, so along one ray this is the
// exact order, for convex and non-convex meshes alike. The image is split
// into tiles, each rasterised and composited (front to back, equal to back to
// front "over") by one thread from the tetrahedra binned to it; fragments tie
// on (depth, tetrahedron index), so the bytes do not depend on the thread count.
// Shared edges follow a top-left fill rule on edge functions computed in a
// canonical vertex order, so each pixel centre is covered once per tetrahedron
// layer. Tetrahedra with a vertex behind the eye (or the orthographic eye
// plane) are not drawn: keep the eye outside the mesh.
// Lit (SPEC §5): each fragment's chord from front to back point is lit by
// ChordLighting: one normal (mode `sampled`), or the shading at both ends
// weighting the weighted tables (mode `interpolated`).
#include "vri/camera.hpp"
#include "vri/volume.hpp"
#include "vri/image.hpp"
#include "vri/render.hpp"
#include "vri/lighting.hpp"
#include "tables/cylindrical_table.hpp"
#include "tables/slab_table.hpp"
#include "tables/weighted_tables.hpp"

namespace vri {

// What pt interpolates across a projected tetrahedron (docs/MESHES.md).
enum class PtReconstruction {
  // vri's `pt`: each pixel's exact (l, s_f, s_b), the front and back points
  // interpolated perspective-correct, fragments sorted per pixel by depth.
  PerPixel,
  // The papers' (Shirley & Tuchman 1990; Roettger & Ertl 2002 as 2002 GPUs
  // drew it; VTK's vtkProjectedTetrahedraMapper): (l, s_f, s_b) at the
  // projected vertices, interpolated linearly in screen space, and the
  // tetrahedra composited in the order of their centres' view depth (a cell
  // centre sort, not exact for every mesh). For the study of the deviation.
  PerVertex,
};

// The tables must cover mesh.max_edge_length() (vri::Error otherwise);
// `weighted` is needed for lighting mode interpolated only.
Image render_projected(const Camera& camera, const TetMesh& mesh, const SlabTable& table,
                       const RenderOptions& options = {}, const Lighting& lighting = {},
                       const WeightedLengthTables* weighted = nullptr,
                       PtReconstruction reconstruction = PtReconstruction::PerPixel);
// pt-cylindrical: the same, each tetrahedron read from the two cylinder planes
// next to its thick vertex's plane (2D lookups, Roettger & Ertl 2002, Sec. 4);
// in mode interpolated the weighted tables on the same planes.
Image render_projected(const Camera& camera, const TetMesh& mesh, const CylindricalTable& table,
                       const RenderOptions& options = {}, const Lighting& lighting = {},
                       const WeightedCylindricalTables* weighted = nullptr);

}  // namespace vri
