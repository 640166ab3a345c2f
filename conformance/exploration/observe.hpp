#pragma once
// Outputs of a run besides its step records, named by path, as text: what the lock-step runner
// compares after the records, and what replay re-checks when a counterexample's divergence is in
// one of them. One definition for both, so a replayed counterexample shows the same texts.
//   "done", "completion_step", "cells[i][j].<field>", "summary.<key>"
#include <cstdio>
#include <optional>
#include <string>

#include "conformance/exploration/summary.hpp"
#include "spec/util/hana_diff.hpp"

namespace swarmcheck::conformance::exploration {

// Whether a divergence path names one of these outputs (and not a field of the step record).
inline bool is_derived_path(const std::string& path) {
  return path == "done" || path == "completion_step" || path.rfind("summary.", 0) == 0 || path.rfind("cells[", 0) == 0;
}

// Sim: the model, the library, or a Simulation (the same accessors). nullopt: not such a path.
template <class Sim>
std::optional<std::string> observe(const Sim& sim, const std::string& path) {
  if (path == "done") return json_io::value_text(sim.done());
  if (path == "completion_step") {
    const auto c = sim.completion_step();
    return c ? std::to_string(*c) : std::string("none");
  }
  if (path.rfind("summary.", 0) == 0) {
    const json_io::Json s = run_summary(sim);
    const std::string key = path.substr(8);
    return s.contains(key) ? s[key].dump() : std::string("absent");
  }
  int i = 0, j = 0, consumed = 0;
  char field[32] = {};
  if (std::sscanf(path.c_str(), "cells[%d][%d].%31[a-z_]%n", &i, &j, field, &consumed) == 3 &&
      consumed == static_cast<int>(path.size())) {
    const int n = sim.scenario().map_size;
    if (i < 0 || j < 0 || i >= n || j >= n) return std::nullopt;
    const json_io::Json cell = json_io::to_json(sim.cell({i, j}));
    return cell.contains(field) ? std::optional<std::string>(cell[field].dump()) : std::nullopt;
  }
  return std::nullopt;
}

}  // namespace swarmcheck::conformance::exploration
