#include "proofs/obligations/kinduction.hpp"

#include <fmt/format.h>

namespace swarmcheck::proofs {
namespace {

// Base case of depth k + 1: a violation on step k from the initial state, the earlier steps
// good. On sat, `out` holds the counterexample.
z3::check_result base_case(Session& session, TransitionSystem& ts, int k, const std::string& label,
                           KInductionResult& out) {
  z3::solver s = session.make_solver();
  s.add(ts.init(0));
  for (int t = 0; t <= k; ++t) s.add(ts.trans(t));
  for (int t = 0; t < k; ++t) s.add(ts.good(t));
  s.add(!ts.good(k));
  const z3::check_result r = session.check(s, label);
  if (r == z3::sat) {
    out.verdict = Verdict::refuted;
    out.depth = k + 1;
    out.model = s.get_model();
  }
  return r;
}

}  // namespace

KInductionResult k_induction(Session& session, TransitionSystem& ts, int max_k,
                             const std::string& label) {
  KInductionResult out;
  for (int k = 0; k <= max_k; ++k) {
    const z3::check_result base = base_case(session, ts, k, fmt::format("{}-base-d{}", label, k + 1), out);
    if (base != z3::unsat) return out;   // refuted, or unknown
    {  // step case: k good steps along a simple path, then a bad one
      z3::solver s = session.make_solver();
      for (int t = 0; t <= k; ++t) s.add(ts.trans(t));
      for (int t = 0; t < k; ++t) s.add(ts.good(t));
      s.add(!ts.good(k));
      for (int a = 0; a <= k; ++a)
        for (int b = a + 1; b <= k; ++b) s.add(ts.differ(a, b));
      const z3::check_result r = session.check(s, fmt::format("{}-step-k{}", label, k));
      if (r == z3::unsat) {
        out.verdict = Verdict::proved;
        out.k = k;
        return out;
      }
      if (r != z3::sat) return out;
    }
  }
  return out;   // the induction did not close within max_k: unknown
}

KInductionResult bounded_check(Session& session, TransitionSystem& ts, int max_depth, const std::string& label) {
  // One query: some step within max_depth from the initial state is bad. The counterexample is
  // cut at its first bad step.
  KInductionResult out;
  z3::solver s = session.make_solver();
  s.add(ts.init(0));
  z3::expr some_bad = s.ctx().bool_val(false);
  for (int t = 0; t < max_depth; ++t) {
    s.add(ts.trans(t));
    some_bad = some_bad || !ts.good(t);
  }
  s.add(some_bad);
  if (session.check(s, fmt::format("{}-bmc-d{}", label, max_depth)) != z3::sat) return out;
  const z3::model m = s.get_model();
  for (int t = 0; t < max_depth; ++t)
    if (!m.eval(ts.good(t), true).is_true()) {
      out.verdict = Verdict::refuted;
      out.depth = t + 1;
      out.model = m;
      return out;
    }
  return out;
}

}  // namespace swarmcheck::proofs
