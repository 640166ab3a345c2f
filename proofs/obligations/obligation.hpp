#pragma once
// A proof obligation: a named property, the verdict we expect Z3 to reach, the assumptions of
// its encoding, and the code that builds the queries and reads Z3's answers.
//
// The verdict always comes from Z3: `proved` when every query of the obligation is unsat,
// `refuted` when a query is sat (its model is the counterexample), `unknown` otherwise.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "proofs/obligations/session.hpp"

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
  std::vector<std::string> reads;         // the spec functions whose definition it encodes
};

// Every obligation, in the order `prove` runs them.
const std::vector<Obligation>& all_obligations();

// The obligations of each file, collected by all_obligations().
std::vector<Obligation> servo_obligations();
std::vector<Obligation> atan2_obligations();
std::vector<Obligation> handshake_obligations();
std::vector<Obligation> handshake_counter_obligations();
std::vector<Obligation> pheromone_obligations();
std::vector<Obligation> occupancy_obligations();
std::vector<Obligation> orientation_obligations();

}  // namespace swarmcheck::proofs
