#pragma once
// Counterexample traces and replay. A counterexample is an ordinary trace (spec/exploration/
// trace.hpp) whose header also carries "impl_options" and "divergence", and whose records are
// the model's, from step 0 to the first step that differs. Replay re-runs the header's scenario
// on the model or the impl and names the first record field that differs from the file.
#include <optional>
#include <string>

#include "conformance/exploration/engine.hpp"
#include "conformance/exploration/generators.hpp"
#include "conformance/exploration/lockstep.hpp"

namespace swarmcheck::conformance::exploration {

// Writes the counterexample trace of case c (nothing half-written: temporary file + rename).
void write_counterexample(const std::string& path, const ExplorationCase& c, const Divergence& d);

struct ReplayResult {
  int64_t records = 0;                  // records compared
  std::optional<Divergence> divergence; // the first record field that differs from the file
  std::optional<std::string> recorded;  // the file's own "divergence", if it is a counterexample
};

// Throws InputError("file:line", ...) for a malformed trace.
// `memory_limit_bytes` (0: none): a trace whose scenario's map would not fit is refused before
// anything is allocated (BudgetExceeded at the header).
ReplayResult replay_trace(const std::string& path, Engine engine, std::uint64_t memory_limit_bytes = 0);

}  // namespace swarmcheck::conformance::exploration
