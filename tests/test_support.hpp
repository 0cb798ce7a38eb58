#pragma once
// Helpers shared by the tests: volumes from formulas, temporary folders,
// running the vri program.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/image.hpp"
#include "vri/transfer_function.hpp"
#include "vri/volume.hpp"

namespace vri::test {

// An image's floats as a vector, for EXPECT_EQ (which prints where they differ).
inline std::vector<float> pixels(const Image& image) { return {image.data().begin(), image.data().end()}; }

// A volume whose sample (i,j,k) is f(x,y,z) at its world position.
template <class F>
GridVolume volume_from(std::array<int, 3> dims, F&& f, Vec3 spacing = {1, 1, 1}, Vec3 origin = {0, 0, 0}) {
  std::vector<float> v;
  v.reserve(std::size_t(dims[0]) * dims[1] * dims[2]);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        v.push_back(static_cast<float>(
            f(origin.x + i * spacing.x, origin.y + j * spacing.y, origin.z + k * spacing.z)));
  return GridVolume(dims, std::move(v), spacing, origin);
}

// The samples as floats, whatever their stored type.
inline std::vector<float> floats(const GridVolume& volume) {
  return volume.visit([](auto v) { return std::vector<float>(v.begin(), v.end()); });
}

// A random piecewise-linear transfer function over [0, s_max]: some runs of
// zero opacity, some narrow spikes, occasional steps (unless steps = false).
inline TransferFunction random_tf(std::mt19937& rng, double s_max, double tau_max, bool steps = true) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<ControlPoint> pts;
  const int n = 3 + int(u(rng) * 6);
  std::vector<double> s(n);
  for (auto& x : s) x = u(rng) * s_max;
  std::sort(s.begin(), s.end());
  for (int i = 0; i < n; ++i) {
    const double tau = u(rng) < 0.3 ? 0.0 : u(rng) * tau_max;
    pts.push_back({s[i], u(rng), u(rng), u(rng), tau});
    if (steps && u(rng) < 0.15) pts.push_back({s[i], u(rng), u(rng), u(rng), u(rng) * tau_max});  // a step
  }
  return TransferFunction(pts);
}

// Ray k of a set that stresses walks over a 41-point grid with 8-cell macro
// cells: through a point on a macro face (x = 8m) and a grid line (y whole),
// along an axis, a face diagonal, the space diagonal or at random (k % 4),
// either way (k % 8 >= 4), starting 100 units back; rounding puts such points
// on either side of a face.
inline Ray ray_along_faces(std::mt19937& rng, int k) {
  std::uniform_real_distribution<double> u(0, 1);
  const Vec3 through{8.0 * int(u(rng) * 6), double(int(u(rng) * 41)), 40 * u(rng)};
  const int kind = k % 4;
  Vec3 dir = kind == 0   ? Vec3{1, 0, 0}
             : kind == 1 ? Vec3{1, 1, 0}
             : kind == 2 ? Vec3{1, 1, 1}
                         : Vec3{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
  if (k % 8 >= 4) dir = -1.0 * dir;
  return {through - 100.0 * dir, dir};
}

// A fresh empty folder under the system temp dir, removed at scope exit.
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    static int counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("vri_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::filesystem::path operator/(const std::string& name) const { return path / name; }
};

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

inline void write_bytes(const std::filesystem::path& p, const std::vector<unsigned char>& bytes) {
  std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

inline std::string source_path(const std::string& rel) { return std::string(VRI_SOURCE_DIR) + "/" + rel; }

// The file names of the bundled scenes (scenes/*.json), sorted; and a test
// name made from one ("neghip_lit.json" -> "neghip_lit").
inline std::vector<std::string> bundled_scenes() {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(source_path("scenes")))
    // (Not hidden files: scripts/float_paths_ab.sh writes scenes/.ab_*.json while it runs.)
    if (e.path().extension() == ".json" && e.path().filename().string()[0] != '.')
      names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}
inline std::string scene_test_name(std::string file) {
  file = file.substr(0, file.size() - 5);
  std::replace(file.begin(), file.end(), '-', '_');
  return file;
}

}  // namespace vri::test
