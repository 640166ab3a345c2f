#pragma once
// k-induction for a safety property of a transition system given as Z3 terms over frames.
//
// A property is a predicate good(t) on transition t (frame t, the inputs of step t, frame t+1).
//   base case, depth d:  init(0), trans(0..d-1), good(0..d-2), not good(d-1)   (BMC)
//   step case, k:        trans(0..k), good(0..k-1), not good(k), frames 0..k pairwise distinct
// For k = 0, 1, ...: a satisfiable base case is a counterexample from the initial state
// (refuted); an unsatisfiable step case after unsatisfiable base cases up to depth k + 1 is a
// proof for every reachable transition (proved). The distinct-frames (simple path) constraint
// makes this complete for finite state spaces. Each query is a fresh solver, logged.
#include <optional>
#include <string>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {

class TransitionSystem {
 public:
  virtual ~TransitionSystem() = default;
  virtual z3::expr init(int frame) = 0;
  virtual z3::expr trans(int step) = 0;
  virtual z3::expr good(int step) = 0;
  virtual z3::expr differ(int frame_a, int frame_b) = 0;
};

struct KInductionResult {
  Verdict verdict = Verdict::unknown;
  int k = -1;                      // proved: the k that closed the induction
  int depth = 0;                   // refuted: the number of steps of the counterexample
  std::optional<z3::model> model;  // refuted: the counterexample
};

KInductionResult k_induction(Session& session, TransitionSystem& ts, int max_k,
                             const std::string& label);

// Bounded model checking alone, one query: a bad step within max_depth steps of the initial
// state. refuted with the counterexample (cut at its first bad step), or unknown when none is
// found (nothing is proved; the query's answer says whether none exists).
KInductionResult bounded_check(Session& session, TransitionSystem& ts, int max_depth, const std::string& label);

}  // namespace swarmcheck::proofs
