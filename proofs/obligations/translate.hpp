#pragma once
// From the spec's symbolic interpretation (spec/util/sym.hpp) to Z3 terms: the rules an
// obligation is about come from spec/, instantiated with num::Symbolic; this file only maps each
// operation to a theory. Nothing here restates a rule.
//
// Reals are interpreted in one of two theories:
//   fp64  IEEE binary64 (fpa_sort<64>), round to nearest even, NaN and infinities included;
//         comparisons and == are IEEE's (fp.lt, fp.eq)
//   real  real arithmetic: no rounding, no NaN (is_nan is false), literals are the exact values
//         of the doubles the code uses
// Functions a theory lacks (atan2, exp, cos, sin, pow, remainder, and sqrt over the reals) are
// uninterpreted, Ackermannized: one constant per application with the facts this file states
// (ranges, signs, quadrants of atan2), and functional consistency between applications. Those
// facts are returned by side_conditions(), to be asserted with the query. A random draw is a
// free integer in its range. A call node (num::traced) is the identity; its name is recorded as a
// spec function the translated expressions read. A sym function node is a Z3 function of that name.
#include <functional>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "proofs/obligations/session.hpp"
#include "proofs/obligations/z3.hpp"
#include "spec/util/sym.hpp"

namespace swarmcheck::proofs {

enum class RealTheory { fp64, real };

class Translator {
 public:
  // consistency: state functional consistency between applications of a function (needed for
  // counterexamples to be real; an obligation whose property never reads those values may skip
  // it: leaving it out only widens what is proved).
  // int_bits > 0 interprets sym integers as signed bit-vectors of that width (indices, counts
  // and draws of a window: decided by bit-blasting, far cheaper than integer arithmetic over
  // nested selects); 0 as mathematical integers.
  Translator(z3::context& ctx, RealTheory theory, bool consistency = true, unsigned int_bits = 0);
  // The same in an obligation's session: the spec functions it translates are the obligation's
  // `reads` (Session::reads).
  Translator(Session& session, RealTheory theory, bool consistency = true, unsigned int_bits = 0);

  z3::expr operator()(const sym::Real& x) { return node(x.node()); }
  z3::expr operator()(const sym::Bool& x) { return node(x.node()); }
  z3::expr operator()(const sym::Int& x) { return node(x.node()); }
  z3::expr node(const sym::NodePtr& n);

  // The Z3 constant of a sym variable of that name and sort (the same constant every time).
  z3::expr variable(const std::string& name, sym::Sort sort);

  // The facts about every uninterpreted application and draw translated so far.
  z3::expr side_conditions() const;
  // The facts added since the last call (for a transition system: the facts of one step).
  z3::expr take_new_facts();

  // Abstracts every real-valued operation (arithmetic, sqrt, the uninterpreted functions) to a
  // fresh value of its sort: an over-approximation, for a property that must hold whatever those
  // values are (a saturation's range). Selects, comparisons and NaN tests stay exact. A model of
  // an abstracted query need not be a run: its counterexamples are for re-asking exactly.
  void abstract_real_arithmetic(bool on) { abstract_ = on; }

  // Translates every call node named fn (a spec function's result, num::traced) as a fresh value
  // of its sort constrained by contract(fresh), without looking inside: for a function whose
  // contract the same obligation proves by other queries (compositional reasoning). The function
  // still counts as read.
  void abstract_call(const std::string& fn, std::function<z3::expr(const z3::expr&)> contract) {
    abstract_calls_[fn] = std::move(contract);
  }

  RealTheory theory() const { return theory_; }
  unsigned int_bits() const { return int_bits_; }
  // The spec functions (call nodes) translated so far.
  const std::set<std::string>& reads() const { return reads_; }
  z3::context& ctx() { return ctx_; }

 private:
  struct Application {
    sym::Op op;
    std::vector<z3::expr> args;
    z3::expr result;
  };
  z3::expr real_literal(double v);
  z3::expr apply(sym::Op op, const std::vector<z3::expr>& args);
  z3::expr arith(const sym::Node& n, const std::vector<z3::expr>& a);

  z3::context& ctx_;
  std::set<std::string>* session_reads_ = nullptr;
  std::set<std::string> reads_;
  RealTheory theory_;
  bool consistency_;
  unsigned int_bits_;
  bool abstract_ = false;
  std::unordered_map<std::string, std::function<z3::expr(const z3::expr&)>> abstract_calls_;
  std::size_t taken_ = 0;
  std::unordered_map<const sym::Node*, z3::expr> memo_;
  std::vector<sym::NodePtr> keep_;   // keeps memoised nodes alive (their addresses are keys)
  std::vector<Application> apps_;
  std::vector<z3::expr> facts_;
  std::vector<std::pair<std::pair<unsigned, unsigned>, z3::expr>> quotients_;
  int fresh_ = 0;
};

// A model's value of a real or FP term as a double (FP: bit-exact; real: nearest double).
double model_double(const z3::model& m, const z3::expr& x);

}  // namespace swarmcheck::proofs
