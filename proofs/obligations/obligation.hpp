#pragma once
// A proof obligation: a named property, the verdict we expect Z3 to reach, the assumptions of
// its encoding, and the code that builds the queries and reads Z3's answers.
//
// The verdict always comes from Z3: `proved` when every query of the obligation is unsat,
// `refuted` when a query is sat (its model is the counterexample), `unknown` otherwise.
//
// What an obligation reads and what the step calls are both read off the code, never listed:
//   reads       the spec functions whose symbolic interpretation its queries translated (the
//               call nodes of num::traced met by its Translators, Session::reads)
//   step_calls  the spec functions the property's quantities pass through in the executed step,
//               interpreted symbolically from the step's entry point (`step` below)
// Every step call must be read (runner.hpp, unread_step_calls): an obligation that restates a
// function on the property's path instead of interpreting it is not met.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "proofs/obligations/session.hpp"
#include "spec/util/sym.hpp"

namespace swarmcheck::proofs {

enum class Verdict { proved, refuted, unknown };

const char* to_string(Verdict v);
Verdict verdict_from_string(const std::string& s);   // throws std::invalid_argument

// A counterexample trace of a protocol obligation (JSON Lines text, see handshake_trace.hpp).
struct TraceFile {
  std::string file_name;   // e.g. "handshake-gauss-seidel.jsonl"
  std::string text;
};

struct Outcome {
  Verdict verdict = Verdict::unknown;
  std::string detail;                 // one or two sentences: what Z3 answered, the model
  std::optional<TraceFile> trace;
};

struct Obligation {
  std::string name;
  std::string property;                   // the property in one sentence
  Verdict expected;
  std::vector<std::string> assumptions;   // what the encoding abstracts or bounds
  std::function<Outcome(Session&)> run;
  // The property's quantities in the executed step, interpreted symbolically from the step's
  // entry point (master_step, the Environment's stages, the controller): their call nodes are
  // the spec functions the property passes through. Empty for an obligation about no step.
  std::function<std::vector<sym::NodePtr>()> step;
};

// Every obligation, in the order `prove` runs them.
const std::vector<Obligation>& all_obligations();

// The obligations of each file, collected by all_obligations().
std::vector<Obligation> servo_obligations();
std::vector<Obligation> atan2_obligations();
std::vector<Obligation> handshake_obligations();
std::vector<Obligation> handshake_counter_obligations();
std::vector<Obligation> handshake_any_robots_obligations();
std::vector<Obligation> pheromone_obligations();
std::vector<Obligation> occupancy_obligations();
std::vector<Obligation> orientation_obligations();

}  // namespace swarmcheck::proofs
