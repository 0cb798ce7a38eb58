// The rule of each numeric method parameter (vri/methods.hpp): the scene
// loader, the command line's overrides, the viewer and Python all reach
// check_method_parameter, so one bad value gets one message everywhere.
#include <cmath>
#include <string>

#include "vri/error.hpp"  // format_g
#include "vri/methods.hpp"

namespace vri {

namespace {

bool positive(double v) { return v > 0 && std::isfinite(v); }
bool whole(double v) { return v == std::floor(v); }
constexpr double k2To53 = 9007199254740992.0;  // JSON's doubles hold every integer up to it

const MethodParameter kParameters[] = {
    {"step", "--step", "a finite number > 0", positive,
     [](const MethodSpec& m) { return double(m.step); }},
    {"tolerance", "--tolerance", "a finite number > 0", positive,
     [](const MethodSpec& m) { return double(m.tolerance); }},
    // The tables' axis: two entries at least, and 4096 (a 256 MiB table) at most.
    {"table_size", "--table-size", "an integer in [2, 4096]", [](double v) { return whole(v) && v >= 2 && v <= 4096; },
     [](const MethodSpec& m) { return double(m.table_size); }},
    {"iterations", "--iterations", "an integer in [1, 4096]", [](double v) { return whole(v) && v >= 1 && v <= 4096; },
     [](const MethodSpec& m) { return double(m.iterations); }},
    {"length_samples", "", "an integer in [2, 4096]", [](double v) { return whole(v) && v >= 2 && v <= 4096; },
     [](const MethodSpec& m) { return double(m.length_samples); }},
    {"planes", "", "0 (the table size) or an integer in [2, 16384]",
     [](double v) { return v == 0 || (whole(v) && v >= 2 && v <= 16384); },
     [](const MethodSpec& m) { return double(m.planes); }},
    {"h0", "--h0", "a finite number > 0", positive,
     [](const MethodSpec& m) { return double(m.h0); }},
    {"hmin", "--hmin", "a finite number > 0", positive,
     [](const MethodSpec& m) { return double(m.hmin); }},
    {"hmax", "--hmax", "a finite number > 0", positive,
     [](const MethodSpec& m) { return double(m.hmax); }},
    // A transmittance threshold: 0 never stops a ray, 1 would stop it at once.
    {"termination", "--termination", "a number in [0, 1)", [](double v) { return v >= 0 && v < 1; },
     [](const MethodSpec& m) { return double(m.fast.termination); }},
    {"max_samples", "--max-samples", "an integer in [1, 2^53]", [](double v) { return whole(v) && v >= 1 && v <= k2To53; },
     [](const MethodSpec& m) { return double(m.max_samples); }},
    {"max_work", "--max-work", "an integer in [1, 2^53]", [](double v) { return whole(v) && v >= 1 && v <= k2To53; },
     [](const MethodSpec& m) { return double(m.max_work); }},
    {"jitter", "--jitter", "an integer in [0, 2^53]", [](double v) { return whole(v) && v >= 0 && v <= k2To53; },
     [](const MethodSpec& m) { return m.jitter ? double(*m.jitter) : 0.0; }},
};

}  // namespace

std::span<const MethodParameter> method_parameters() { return kParameters; }

void check_method_parameter(std::string_view key, double value) {
  for (const MethodParameter& p : kParameters) {
    if (p.key != key) continue;
    if (p.holds(value)) return;
    std::string message = "method.";
    message.append(key);
    if (!p.flag.empty()) message.append(" (").append(p.flag).append(")");
    message.append(": expected ").append(p.expects);
    message.append(", found ").append(format_g(value));
    throw Error(message);
  }
  throw Error("no method parameter '" + std::string(key) + "'");
}

void check_method_parameters(const MethodSpec& m) {
  for (const MethodParameter& p : kParameters) check_method_parameter(p.key, p.of(m));
}

}  // namespace vri
