#pragma once
// The JSON forms of a transfer function (SPEC §3 and §8, issue 20; every form
// and default in docs/SCENES.md, "Transfer functions"):
//   {"points": [[s, r, g, b, tau], ...]}
//   {"opacity_points": [[s, r, g, b, a], ...], "unit_distance": u}
//   {"colormap": NAME, "opacity": [[x, tau], ...], "unit_distance": d}
//   {"paraview": FILE, "name": PRESET, "opacity": [[x, tau], ...], "unit_distance": d}
// each with an optional "range": [lo, hi], "data" or {"percentiles": [p_lo, p_hi]}.
// A request is read and checked without the volume; resolve() then spreads it
// over its range, which for "data" and percentiles is the volume's.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vri/scene.hpp"
#include "vri/transfer_function.hpp"
#include "transfer/paraview_colormap.hpp"

namespace vri {

class TransferFunctionRequest {
 public:
  // `file` names the source in messages ("scene 'a.json'"), `path` the key
  // path of `j` in it ("transfer_function"; "" at the top of a file); `base`
  // is where a relative "paraview" path resolves; `may_name_file`: "file" is
  // one of the known keys (a scene's block, whose "file" the caller reads).
  // Every problem is a vri::Error (FileError for a file that cannot be read)
  // with one line naming the file and the key.
  TransferFunctionRequest(const nlohmann::json& j, std::string file, std::string path, std::filesystem::path base,
                          bool may_name_file = false);

  // Whether resolve() needs the volume: a "range" of "data" or percentiles,
  // or a colour map without "range".
  bool needs_volume() const;
  // The transfer function over its range; `volume` may be null when
  // needs_volume() is false (vri::Error naming the key otherwise).
  TransferFunction resolve(const Volume* volume) const;

  // How much a range of one value is widened (upwards): max(|lo|, 1) times this.
  static constexpr double kWiden = 1.0 / (1 << 20);

 private:
  struct Range {
    enum class Kind { Given, Data, Percentiles } kind;
    double a = 0, b = 0;    // [lo, hi] or [p_lo, p_hi]
    bool implicit = false;  // a colour map's "data", not written
  };
  enum class Form { Points, Colormap, Paraview };

  std::string where(const std::string& key) const;
  std::string ctx() const;
  std::optional<Range> read_range(const nlohmann::json& j) const;
  std::vector<TauPoint> read_opacity(const nlohmann::json& j) const;

  std::string file_, path_;
  Form form_ = Form::Points;
  std::optional<Range> range_;
  std::vector<ControlPoint> points_;      // Points: checked by a TransferFunction
  std::vector<ColormapPoint> colors_;     // Colormap (x in [0, 1]), Paraview (the file's x)
  std::vector<TauPoint> opacity_;
  bool opacity_relative_ = true;          // x in [0, 1] of the range, else the file's x
};

// A transfer-function file (its own source name; "paraview" relative to its folder).
TransferFunctionRequest transfer_function_request(const std::filesystem::path& path);

}  // namespace vri
