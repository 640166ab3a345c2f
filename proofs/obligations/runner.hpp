#pragma once
// Runs obligations, each in a child process under a watchdog, so that `prove` never hangs: a
// query that ignores its Z3 timeout (nonlinear arithmetic can) is killed at the deadline and
// reported as unknown. The child sends its report back as JSON through a pipe; the parent
// writes no files (the verb does, whole or not at all).
#include <optional>
#include <string>
#include <vector>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {

struct ObligationReport {
  std::string name;
  std::string property;
  Verdict expected = Verdict::unknown;
  std::vector<std::string> assumptions;
  std::vector<std::string> reads;        // the spec functions its queries interpreted (sorted)
  std::vector<std::string> step_calls;   // the spec functions the property passes through in the step
  std::vector<std::string> unread;       // step_calls not in reads: the encoding restates them
  Verdict result = Verdict::unknown;
  double seconds = 0;
  std::string detail;
  std::vector<QueryRecord> queries;
  std::optional<TraceFile> trace;
  // As expected, and reading every function the step calls on the property's path.
  bool met() const { return result == expected && unread.empty(); }
};

// The watchdog's default: seconds an obligation may take before its prover is killed.
inline constexpr double kObligationTimeoutS = 120;

// Runs o in a forked child; after timeout_s seconds the child is killed (result unknown).
// query_timeout_ms bounds each Z3 query inside the child.
ObligationReport run_isolated(const Obligation& o, double timeout_s, unsigned query_timeout_ms);

// Runs o in this process (no watchdog): for tests and debugging.
ObligationReport run_in_process(const Obligation& o, unsigned query_timeout_ms);

// The step calls an obligation's reads leave out, in step order.
std::vector<std::string> unread_step_calls(const std::vector<std::string>& step_calls,
                                           const std::vector<std::string>& reads);

// The obligation with this name, or nullptr.
const Obligation* find_obligation(const std::string& name);

}  // namespace swarmcheck::proofs
