#include "vri/methods.hpp"

#include <algorithm>

#include "adaptive/adaptive_params.hpp"
#include "exact/exact.hpp"
#include "exact/mesh_exact.hpp"
#include "preint/preint1.hpp"
#include "preint/preint2.hpp"
#include "preint2_dual/preint2_dual.hpp"
#include "projected/projected_scene_renderer.hpp"
#include "riemann/riemann.hpp"
#include "tet_raycast/tet_raycast.hpp"
#include "vri/error.hpp"

// A GPU renderer exists in a build with the Vulkan backend only.
#if VRI_VULKAN
#define VRI_GPU(maker) maker
#else
#define VRI_GPU(maker) nullptr
#endif

namespace vri {

const std::vector<MethodInfo>& methods() {
  // clang-format off
  static const std::vector<MethodInfo> all = {
      {.name = "riemann", .paper = "Riemann sum of the emission-absorption integral (SPEC §4; Max 1995)",
       .grid = true, .gpu_grid = true, .distributed = true, .termination = true, .jitter = true, .step_parameter = "step",
       .parameters = {"step"},
       .make_grid = make_riemann, .make_gpu = VRI_GPU(make_vulkan_riemann)},
      {.name = "preint1", .paper = "pre-integrated classification (Engel, Kraus & Ertl 2001); tables by Lum, Wilson & "
                                   "Ma 2004 and Roettger & Ertl 2002",
       .grid = true, .gpu_grid = true, .distributed = true, .termination = true, .step_parameter = "step",
       .parameters = {"step", "table_size", "builder"},
       .make_grid = make_preint1, .make_gpu = VRI_GPU(make_vulkan_preint)},
      {.name = "preint2", .paper = "second-order pre-integration (El Hajjar, Marchesin, Dischler & Mongenet 2008)",
       .grid = true, .gpu_grid = true, .distributed = true, .termination = true, .step_parameter = "step",
       .parameters = {"step", "table_size", "iterations", "builder"},
       .make_grid = make_preint2, .make_gpu = VRI_GPU(make_vulkan_preint)},
      {.name = "preint2-dual", .paper = "second-order pre-integration on the cell walk (El Hajjar et al. 2008, §4)",
       .grid = true, .gpu_grid = true, .distributed = true, .termination = true,
       .parameters = {"table_size", "iterations", "builder"},
       .make_grid = make_preint2_dual, .make_gpu = VRI_GPU(make_vulkan_preint2_dual)},
      {.name = "adaptive", .paper = "adaptive Simpson with error control (Campagnolo, Celes & de Figueiredo 2015)",
       .grid = true, .gpu_grid = true, .distributed = true, .step_parameter = "hmin",
       .parameters = {"tolerance", "h0", "hmin", "hmax", "strategy"},
       .make_grid = make_adaptive, .make_gpu = VRI_GPU(make_vulkan_adaptive)},
      {.name = "exact", .paper = "the integral in closed form between control points (SPEC §4), the reference",
       .grid = true, .mesh = true, .distributed = true, .parameters = {"tolerance"},
       .make_grid = make_exact, .make_mesh = make_mesh_exact},
      {.name = "pt", .paper = "projected tetrahedra (Shirley & Tuchman 1990) with the (l, s_f, s_b) table "
                              "(Roettger & Ertl 2002)",
       .mesh = true, .per_ray = false, .parameters = {"table_size", "length_samples", "builder"},
       .make_projected = make_pt},
      {.name = "pt-cylindrical", .paper = "projected tetrahedra on the cylindrical table (Roettger & Ertl 2002, §4)",
       .mesh = true, .per_ray = false, .parameters = {"table_size", "length_samples", "planes", "builder"},
       .make_projected = make_pt_cylindrical},
      {.name = "tet-raycast", .paper = "cell-to-cell ray casting (Garrity 1990) with the (l, s_f, s_b) table",
       .mesh = true, .gpu_mesh = true, .parameters = {"table_size", "length_samples", "builder"},
       .make_mesh = make_tet_raycast, .make_gpu = VRI_GPU(make_vulkan_tet_raycast)},
  };
  // clang-format on
  return all;
}

namespace {

// "a, b, c" - or, with last = " and ", "a, b and c".
std::string join(bool (*keep)(const MethodInfo&), std::string_view last) {
  std::vector<std::string_view> names;
  for (const MethodInfo& m : methods())
    if (!keep || keep(m)) names.push_back(m.name);
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) list += i + 1 == names.size() ? last : ", ";
    list += names[i];
  }
  return list;
}

}  // namespace

const MethodInfo* find_method(std::string_view name) {
  const auto& all = methods();
  const auto it = std::find_if(all.begin(), all.end(), [&](const MethodInfo& m) { return m.name == name; });
  return it == all.end() ? nullptr : &*it;
}

std::string method_names(bool (*keep)(const MethodInfo&), std::string_view conjunction) {
  std::string last(" ");  // built in steps: GCC 12 warns (-Wrestrict) on " " + std::string(...) + " "
  last.append(conjunction).append(" ");
  return join(keep, last);
}

const MethodInfo& known_method(std::string_view name) {
  if (const MethodInfo* m = find_method(name)) return *m;
  throw Error("unknown method '" + std::string(name) + "' (known: " + join(nullptr, ", ") + ")");
}

}  // namespace vri
