#pragma once
// Session: the Z3 context of one obligation, and the log of every query it checked, so that
// `prove --smt2` can write each query as SMT-LIB2 together with the answer Z3 gave here.
#include <set>
#include <string>
#include <vector>

#include "proofs/obligations/z3.hpp"

namespace swarmcheck::proofs {

struct QueryRecord {
  std::string label;    // short, file-name safe: "step-n3-k2"
  std::string smt2;     // the solver's assertions as SMT-LIB2, ending in (check-sat)
  std::string answer;   // "sat", "unsat" or "unknown", as the C++ API answered
  double seconds = 0;   // how long the C++ API took to answer
};

// Every query is bounded by Z3's resource limit, a count of its inner steps (about two million
// a second of CPU on this machine): a verdict that does not depend on how loaded the machine is.
// The wall-clock timeout is a backstop only (a tactic that ignores the resource limit).
inline constexpr unsigned kQueryRlimit = 50'000'000;
inline constexpr unsigned kQueryTimeoutMs = 120'000;

class Session {
 public:
  explicit Session(unsigned timeout_ms = kQueryTimeoutMs) : timeout_ms_(timeout_ms) {}
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  z3::context& ctx() { return ctx_; }
  // A solver for linear, UF, bit-vector and floating-point queries, with the timeout set.
  z3::solver make_solver();
  // A solver for nonlinear real arithmetic: the qfnra-nlsat tactic (VERIFICATION.md: the
  // default solver may give up or ignore its timeout on these).
  z3::solver make_nonlinear_solver();
  // A solver that simplifies, solves equations and eliminates term-level if-then-else before
  // the SMT core: queries that unroll a rule's selects over integers and reals (the choice) are
  // instant this way and can time out without it. Check its queries with check_preprocessed.
  z3::solver make_preprocessed_solver();
  // The SMT core alone (no tactic chosen by probes): for queries over uninterpreted functions,
  // integers and a few nonlinear products (the symbolic grid's), where the probe-chosen tactic can
  // wander for seconds that the core needs milliseconds for. Check its queries with check_smt.
  z3::solver make_smt_solver();
  z3::check_result check_smt(z3::solver& s, const std::string& label);
  // Checks the solver's assertions and logs the query and its answer.
  z3::check_result check(z3::solver& s, const std::string& label);
  // The same for a make_preprocessed_solver() solver: its SMT-LIB2 names the same tactic.
  z3::check_result check_preprocessed(z3::solver& s, const std::string& label);

  const std::vector<QueryRecord>& queries() const { return queries_; }
  // The spec functions the obligation's queries read (the call nodes its translators met).
  std::set<std::string>& reads() { return reads_; }

 private:
  unsigned timeout_ms_;
  z3::context ctx_;
  std::vector<QueryRecord> queries_;
  std::set<std::string> reads_;
};

const char* to_string(z3::check_result r);

}  // namespace swarmcheck::proofs
