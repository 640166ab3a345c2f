#include "proofs/obligations/session.hpp"

#include <chrono>

namespace swarmcheck::proofs {

const char* to_string(z3::check_result r) {
  switch (r) {
    case z3::sat: return "sat";
    case z3::unsat: return "unsat";
    default: return "unknown";
  }
}

z3::solver Session::make_solver() {
  z3::solver s(ctx_);
  s.set("timeout", timeout_ms_);
  s.set("rlimit", kQueryRlimit);
  return s;
}

z3::solver Session::make_nonlinear_solver() {
  z3::solver s = z3::tactic(ctx_, "qfnra-nlsat").mk_solver();
  s.set("timeout", timeout_ms_);
  s.set("rlimit", kQueryRlimit);
  return s;
}

namespace {
constexpr const char* kPreprocess = "(then simplify propagate-values solve-eqs elim-term-ite simplify smt)";
}

z3::solver Session::make_preprocessed_solver() {
  const z3::tactic t = z3::tactic(ctx_, "simplify") & z3::tactic(ctx_, "propagate-values") &
                       z3::tactic(ctx_, "solve-eqs") & z3::tactic(ctx_, "elim-term-ite") &
                       z3::tactic(ctx_, "simplify") & z3::tactic(ctx_, "smt");
  z3::solver s = t.mk_solver();
  s.set("timeout", timeout_ms_);
  s.set("rlimit", kQueryRlimit);
  return s;
}

z3::solver Session::make_smt_solver() {
  z3::solver s = z3::tactic(ctx_, "smt").mk_solver();
  s.set("timeout", timeout_ms_);
  s.set("rlimit", kQueryRlimit);
  return s;
}

z3::check_result Session::check_smt(z3::solver& s, const std::string& label) {
  const z3::check_result r = check(s, label);
  std::string& text = queries_.back().smt2;
  const std::string plain = "(check-sat)";
  const std::size_t at = text.rfind(plain);
  if (at != std::string::npos) text.replace(at, plain.size(), "(check-sat-using smt)");
  return r;
}

z3::check_result Session::check_preprocessed(z3::solver& s, const std::string& label) {
  const z3::check_result r = check(s, label);
  std::string& text = queries_.back().smt2;
  const std::string plain = "(check-sat)";
  const std::size_t at = text.rfind(plain);
  if (at != std::string::npos) text.replace(at, plain.size(), std::string("(check-sat-using ") + kPreprocess + ")");
  return r;
}

z3::check_result Session::check(z3::solver& s, const std::string& label) {
  // to_smt2() already ends in (check-sat).
  QueryRecord q{label, s.to_smt2(), "", 0};
  const auto start = std::chrono::steady_clock::now();
  const z3::check_result r = s.check();
  q.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  q.answer = to_string(r);
  queries_.push_back(std::move(q));
  return r;
}

}  // namespace swarmcheck::proofs
