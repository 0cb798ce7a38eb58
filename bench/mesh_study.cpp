// Accuracy study of the mesh methods against the mesh `exact` (tolerance 1e-6):
// tet-raycast, pt and pt-cylindrical with n/2, n, 2n and 4n planes (n = the
// table size) and, for the cylinder planes, tiles of n and 4n a side. Prints
// a Markdown table of max and RMS absolute differences over all channels.
// Run: ./build/bench/mesh_study scenes/blunt_fin.json [SIZE]   (docs/MESHES.md)
#include <cmath>
#include <cstdio>
#include <string>

#include "vri/methods.hpp"
#include "methods/mesh_tables.hpp"
#include "methods/projected/projected_tetrahedra.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/cylindrical_table.hpp"

namespace {

void row(const std::string& what, const vri::Image& a, const vri::Image& b) {
  double mx = 0, ss = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) {
    const double d = std::abs(double(a.data()[i]) - b.data()[i]);
    mx = std::max(mx, d);
    ss += d * d;
  }
  std::printf("| %s | %.2e | %.2e |\n", what.c_str(), mx, std::sqrt(ss / a.data().size()));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: mesh_study SCENE.json [SIZE]\n");
    return 2;
  }
  vri::Scene s = vri::load_scene(argv[1]);
  if (argc > 2) s.camera.width = s.camera.height = std::stoi(argv[2]);
  const vri::Camera cam(s.camera);
  const vri::TetMesh& mesh = s.mesh();
  const int n = s.method.table_size;
  std::printf("mesh: %zu tetrahedra, table %d x %d x %d lengths, image %dx%d\n\n", mesh.size(), n, n,
              s.method.length_samples, cam.width(), cam.height());
  vri::MethodSpec spec = s.method;
  spec.name = "exact";
  spec.tolerance = 1e-6;
  const vri::Image exact = vri::render(cam, *vri::make_integrator(spec, mesh, s.transfer_function));
  std::printf("| method vs exact | max | RMS |\n|---|---|---|\n");
  spec.name = "tet-raycast";
  row("tet-raycast", exact, vri::render(cam, *vri::make_integrator(spec, mesh, s.transfer_function)));
  const auto table = vri::make_slab_table(spec, mesh, s.transfer_function);
  const vri::Image pt = vri::render_projected(cam, mesh, *table);
  row("pt", exact, pt);
  row("pt, per-vertex (the papers': screen-linear (l, s_f, s_b), cell-centre sort)", exact,
      vri::render_projected(cam, mesh, *table, {}, {}, nullptr, vri::PtReconstruction::PerVertex));
  for (int planes : {n / 2, n, 2 * n, 4 * n})
    row("pt-cylindrical, " + std::to_string(planes) + " planes", exact,
        vri::render_projected(cam, mesh, vri::CylindricalTable(*table, n, planes)));
  std::printf("\n| pt-cylindrical vs pt | max | RMS |\n|---|---|---|\n");
  for (int tile : {n, 4 * n})
    for (int planes : {n / 2, n, 2 * n, 4 * n}) {
      if (double(tile) * tile * planes > 1 << 26) continue;  // the table's size limit
      row(std::to_string(planes) + " planes, tiles " + std::to_string(tile) + "^2", pt,
          vri::render_projected(cam, mesh, vri::CylindricalTable(*table, tile, planes)));
    }
  return 0;
}
