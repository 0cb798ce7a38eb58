#pragma once
// Running the vri program from a test: exit code, stdout and stderr.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.hpp"

namespace vri::test {

struct ProcessResult {
  int code;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `prefix` runs before the program in the same shell (e.g. "ulimit -v N;").
inline ProcessResult run(const std::string& args, const TempDir& dir, const std::string& prefix = "") {
  const auto out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string cmd = prefix + "exec " + std::string(VRI_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  // A crash (a signal) reads as -1.
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

inline std::string scene_with(const TempDir& dir, const std::string& body, const std::string& name = "scene.json") {
  const auto p = dir / name;
  write_text(p, body);
  return p.string();
}

// A 12^3 sphere seen from +z by a 16x12 camera, rendered with `exact`.
inline const std::string kGoodScene = R"({"volume": {"builtin": "sphere", "dims": [12, 12, 12]},
  "transfer_function": {"points": [[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]]},
  "camera": {"eye": [5.5, 5.5, 40], "target": [5.5, 5.5, 5.5], "width": 16, "height": 12},
  "method": {"name": "exact", "tolerance": 1e-5}})";

}  // namespace vri::test
