#include "mesh/tetrahedralize.hpp"

#include <string>

#include "vri/error.hpp"
#include "vri/memory.hpp"

namespace vri {

namespace {

// Cell corners are numbered by bits: bit 0 = +x, bit 1 = +y, bit 2 = +z.
// Five tetrahedra for a cell with even i+j+k: the corners of odd local bit
// sum (1, 2, 4, 7) form the centre; odd cells use the mirror image (bits flipped in x).
constexpr int kFiveEven[5][4] = {{1, 2, 4, 7}, {0, 1, 2, 4}, {3, 1, 2, 7}, {5, 1, 4, 7}, {6, 2, 4, 7}};
constexpr int kFiveOdd[5][4] = {{0, 3, 5, 6}, {1, 0, 3, 5}, {2, 0, 3, 6}, {4, 0, 5, 6}, {7, 3, 5, 6}};
// Kuhn: one tetrahedron per order in which the axes are stepped from 0 to 7.
constexpr int kSix[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7}, {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};

}  // namespace

TetMesh tetrahedralize(const GridVolume& grid, int tets_per_cell) {
  if (tets_per_cell != 5 && tets_per_cell != 6)
    throw Error("tetrahedralize: tets per cell must be 5 or 6, got " + std::to_string(tets_per_cell));
  const auto& n = grid.dims();
  const Vec3 sp = grid.spacing(), org = grid.origin();
  const std::size_t cells = std::size_t(n[0] - 1) * (n[1] - 1) * (n[2] - 1);
  if (grid.size() > std::size_t{INT32_MAX} / 2 || cells * tets_per_cell > std::size_t{INT32_MAX})
    throw Error("tetrahedralize: the grid is too large for a mesh");
  // What is built here, held until the mesh has taken it, and the mesh itself
  // on top: refused before anything is allocated when both do not fit.
  const std::uint64_t building = grid.size() * (sizeof(Vec3) + sizeof(float)) + cells * tets_per_cell * sizeof(TetMesh::Tet);
  const std::string what = "a tetrahedralized mesh of " + std::to_string(cells * tets_per_cell) + " tetrahedra";
  check_allocation(building + TetMesh::bytes_for(grid.size(), cells * tets_per_cell), what);
  const MemoryCharge charge(building, what);
  std::vector<Vec3> points;
  points.reserve(grid.size());
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) points.push_back({org.x + i * sp.x, org.y + j * sp.y, org.z + k * sp.z});
  std::vector<TetMesh::Tet> tets;
  tets.reserve(cells * tets_per_cell);
  for (int k = 0; k + 1 < n[2]; ++k)
    for (int j = 0; j + 1 < n[1]; ++j)
      for (int i = 0; i + 1 < n[0]; ++i) {
        std::int32_t corner[8];
        for (int c = 0; c < 8; ++c)
          corner[c] = static_cast<std::int32_t>(grid.index(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1)));
        auto emit = [&](const int(*pattern)[4], int count) {
          for (int t = 0; t < count; ++t)
            tets.push_back({corner[pattern[t][0]], corner[pattern[t][1]], corner[pattern[t][2]], corner[pattern[t][3]]});
        };
        if (tets_per_cell == 6) emit(kSix, 6);
        else emit((i + j + k) % 2 == 0 ? kFiveEven : kFiveOdd, 5);
      }
  return TetMesh(std::move(points), std::move(tets),
                 grid.visit([](auto v) { return std::vector<float>(v.begin(), v.end()); }));
}

}  // namespace vri
