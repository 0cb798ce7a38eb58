// vri-verify: the verification campaign (issue 46, docs/VERIFICATION.md).
//   vri-verify [--first SEED] [--cases N] [--report FILE.md] [--list K] [--scenes]
// generates cases SEED .. SEED+N-1 (case_generator.hpp), runs every check of
// case_checks.hpp on each, prints the violations per check and per family and
// writes them as Markdown to FILE.md; exits 1 if any check other than the
// ones named with --open (known open classes) was violated. --scenes prints
// each case's scene (JSON, one a line) instead, to replay with `vri render`.
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>

#include "verification/case_checks.hpp"

namespace {

struct Tally {
  long cases = 0;
  std::map<std::string, long> by_check;                            // check -> cases violating it
  std::map<std::string, std::map<std::string, long>> by_family;    // check -> family -> cases
  std::map<std::string, std::map<std::string, long>> family_cases; // family axis -> family -> cases
  std::map<std::string, std::vector<std::string>> examples;        // check -> "seed: method: detail"
};

}  // namespace

int main(int argc, char** argv) {
  std::uint64_t first = 0;
  long cases = 100;
  std::string report;
  std::set<std::string> open;
  std::size_t list = 5;
  bool scenes = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "vri-verify: %s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--first") first = std::stoull(value());
    else if (a == "--cases") cases = std::stol(value());
    else if (a == "--report") report = value();
    else if (a == "--open") open.insert(value());
    else if (a == "--list") list = std::stoul(value());
    else if (a == "--scenes") scenes = true;
    else {
      std::fprintf(stderr, "vri-verify: unknown argument '%s'\n", a.c_str());
      return 2;
    }
  }
  if (scenes) {
    for (long k = 0; k < cases; ++k) std::printf("%s\n", vri::verify::make_case(first + std::uint64_t(k)).json.c_str());
    return 0;
  }
  Tally t;
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::vector<vri::verify::Violation>> found(cases);
  std::vector<std::optional<vri::verify::Case>> made(cases);
  // Cases on every core; the tally in seed order after, so the report does
  // not depend on the scheduling.
  tbb::parallel_for(0L, cases, [&](long k) {
    made[k].emplace(vri::verify::make_case(first + std::uint64_t(k)));
    found[k] = vri::verify::check_case(*made[k]);
  });
  for (long k = 0; k < cases; ++k) {
    const std::uint64_t seed = first + std::uint64_t(k);
    const vri::verify::Case& c = *made[k];
    const auto& violations = found[k];
    ++t.cases;
    for (const auto& f : c.families) ++t.family_cases[f.substr(0, f.find(':'))][f];
    std::set<std::string> checks;
    for (const auto& v : violations) {
      if (checks.insert(v.check).second) {
        ++t.by_check[v.check];
        for (const auto& f : c.families) ++t.by_family[v.check][f];
        if (t.examples[v.check].size() < list)
          t.examples[v.check].push_back(std::to_string(seed) + ": " + v.method + ": " + v.detail + "\n    " + c.json);
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream md;
  md << "Cases " << first << " .. " << first + std::uint64_t(cases) - 1 << " (" << t.cases << "), " << seconds
     << " s.\n\n| check | cases violating it | families most involved |\n|---|---|---|\n";
  static const char* kChecks[] = {"finite", "alpha-range", "colour-bound", "exact-vs-independent",
                                  "guaranteed", "threads", "skipping", "table-convergence", "float-vs-double",
                                  "preint2-vs-preint1"};
  bool failed = false;
  for (const char* check : kChecks) {
    const long n = t.by_check.count(check) ? t.by_check[check] : 0;
    std::string families;
    if (n > 0) {
      std::vector<std::pair<long, std::string>> f;
      for (const auto& [family, count] : t.by_family[check]) f.push_back({-count, family});
      std::sort(f.begin(), f.end());
      for (std::size_t i = 0; i < f.size() && i < 4; ++i)
        families += (i ? ", " : "") + f[i].second + " " + std::to_string(-f[i].first);
      if (!open.count(check)) failed = true;
    }
    md << "| " << check << (open.count(check) ? " (open)" : "") << " | " << n << " | " << families << " |\n";
  }
  md << "\nCases per family:\n\n";
  for (const auto& [axis, families] : t.family_cases) {
    md << "- " << axis << ":";
    for (const auto& [family, count] : families) md << " " << family.substr(axis.size() + 1) << " " << count << ";";
    md << "\n";
  }
  for (const auto& [check, list_of] : t.examples) {
    md << "\nFirst cases violating " << check << " (seed: method: numbers, then the scene):\n\n```\n";
    for (const auto& e : list_of) md << e << "\n";
    md << "```\n";
  }
  std::fputs(md.str().c_str(), stdout);
  if (!report.empty()) std::ofstream(report) << md.str();
  return failed ? 1 : 0;
}
