// Obligation handshake-safety-any-robots: the Jacobi flag handshake keeps no-early-plan and
// fresh-acceptance for EVERY number of robots, by a counter abstraction. The controllers are
// identical, so a state of the system is the Environment's (flag, output) and how many
// controllers are in each local class (output, maneuver, and the ghosts reached and fresh);
// the number of robots N is a free integer >= 1.
//
// The local steps come from the code: for each (output, maneuver) of a controller and each
// Environment output it reads, Z3 enumerates which (output', maneuver', robot at its waypoint)
// the spec's controller_rule allows for some pose, heading, waypoint and tolerances. A system
// step moves the counts along those local steps (non-negative integer flows; each controller's
// inputs are its own), and the Environment plans through environment_handshake_rule with
// all-arrived = no controller with a lowered output. k-induction with the counting form of the
// hand-derived lemma (handshake_encoding.cpp) closes the proof for all N at once.
#include <array>
#include <fmt/format.h>
#include <vector>

#include "proofs/obligations/handshake_lemmas.hpp"
#include "proofs/obligations/handshake_system.hpp"
#include "proofs/obligations/kinduction.hpp"
#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/master.hpp"

namespace swarmcheck::proofs {
namespace {

using S = num::Symbolic;
constexpr int kClasses = 16;   // out * 8 + driving * 4 + reached * 2 + fresh

struct LocalClass {
  bool out, driving, reached, fresh;
};
LocalClass class_of(int c) { return {(c & 8) != 0, (c & 4) != 0, (c & 2) != 0, (c & 1) != 0}; }
int class_index(bool out, bool driving, bool reached, bool fresh) {
  return (out ? 8 : 0) + (driving ? 4 : 0) + (reached ? 2 : 0) + (fresh ? 1 : 0);
}

struct ControllerMove {   // what controller_rule allows from (out, driving) reading env_out
  bool out, driving, at;
};

// [out][driving][env_out] -> the moves controller_rule allows, enumerated by Z3.
using MoveTable = std::array<std::array<std::array<std::vector<ControllerMove>, 2>, 2>, 2>;

bool enumerate_moves(Session& session, MoveTable& table) {
  z3::context& c = session.ctx();
  for (int out = 0; out < 2; ++out)
    for (int drv = 0; drv < 2; ++drv)
      for (int eo = 0; eo < 2; ++eo) {
        Translator t(session, RealTheory::real, false);
        exploration::ControllerParamsT<S> p = exploration::symbolic_controller_params(exploration::RobotParams{});
        p.tolerance_m = sym::Real::var("tolerance");
        p.orient_tolerance_rad = sym::Real::var("orient_tolerance");
        p.reorient_rad = sym::Real::var("reorient");
        const sym::Real x = sym::Real::var("x"), y = sym::Real::var("y"), theta = sym::Real::var("theta"),
                        wx = sym::Real::var("wx"), wy = sym::Real::var("wy");
        const exploration::ControllerCoreT<S> after = handshake::traced_controller_rule(
            p,
            {sym::Bool(out == 1), sym::Bool(drv == 1), sym::Real::var("beta"), sym::Real(0.0), sym::Real(0.0),
             sym::Real::var("target")},
            {x, y, theta, wx, wy, sym::Bool(eo == 1), sym::Real(handshake::kHandshakeStep_s)});
        const z3::expr o = t(after.idle), d = t(after.driving);
        auto magnitude = [](const z3::expr& v) { return z3::ite(v < 0, -v, v); };
        const z3::expr at = magnitude(t(wx) - t(x)) + magnitude(t(wy) - t(y)) < t(p.tolerance_m);   // the property's
        z3::solver s = session.make_solver();
        s.add(t.side_conditions() && t(p.tolerance_m) > 0 && t(p.orient_tolerance_rad) > 0 && t(p.reorient_rad) > 0);
        for (int n = 0; n <= 8; ++n) {
          const z3::check_result r = session.check(s, fmt::format("moves-o{}-d{}-e{}-{}", out, drv, eo, n));
          if (r == z3::unsat) break;
          if (r != z3::sat) return false;
          const z3::model m = s.get_model();
          const ControllerMove mv{m.eval(o, true).is_true(), m.eval(d, true).is_true(), m.eval(at, true).is_true()};
          table[out][drv][eo].push_back(mv);
          s.add(!(o == c.bool_val(mv.out) && d == c.bool_val(mv.driving) && at == c.bool_val(mv.at)));
        }
      }
  return true;
}

// The controllers as master_step sees them in the counter abstraction: the counts of the
// classes whose output is lowered.
struct CountedControllers {
  std::vector<z3::expr> lowered;
};

// What the Environment reads of counted controllers (master_step's environment_input): all
// arrived iff no controller has a lowered output. all-arrived-any-robots proves all_arrived_rule
// is exactly that for every number of controllers (run first, below).
z3::expr environment_input(const CountedControllers& c) {
  z3::expr n = c.lowered.front().ctx().int_val(0);
  for (const z3::expr& x : c.lowered) n = n + x;
  return n == 0;
}

class CounterEncoding : public TransitionSystem {
 public:
  CounterEncoding(Session& session, const MoveTable& moves)
      : session_(&session), c_(session.ctx()), moves_(moves), n_(c_.int_const("robots")) {}

  z3::expr init(int t) override {
    z3::expr r = flag(t) && !eout(t) && n_ >= 1;
    const int start = class_index(exploration::initial_controller().on_destination_output == 1,
                                  exploration::initial_controller().maneuver == 2, true, false);
    for (int k = 0; k < kClasses; ++k) r = r && count(t, k) == (k == start ? n_ : c_.int_val(0));
    return r;
  }

  z3::expr trans(int t) override { return step(t).eq; }

  z3::expr good(int t) override { return !step(t).early && !step(t).stale && lemma(t) && lemma(t + 1); }

  z3::expr differ(int a, int b) override {
    z3::expr d = flag(a) != flag(b) || eout(a) != eout(b);
    for (int k = 0; k < kClasses; ++k) d = d || count(a, k) != count(b, k);
    return d;
  }

  // Counting form of Encoding::lemma: every count non-negative and summing to N; just planned
  // (output 1): flag 0 and every controller idle, not yet at its new waypoint, with a fresh one;
  // waiting (output 0): flag 1, no idle controller that has not reached its waypoint, nothing fresh.
  z3::expr lemma(int t) {
    z3::expr sum = c_.int_val(0), bad_planned = c_.int_val(0), bad_waiting = c_.int_val(0), pos = c_.bool_val(true);
    for (int k = 0; k < kClasses; ++k) {
      const LocalClass l = class_of(k);
      sum = sum + count(t, k);
      pos = pos && count(t, k) >= 0;
      if (!(l.out && !l.reached && l.fresh)) bad_planned = bad_planned + count(t, k);
      if ((l.out && !l.reached) || l.fresh) bad_waiting = bad_waiting + count(t, k);
    }
    return pos && sum == n_ && z3::implies(eout(t), !flag(t) && bad_planned == 0) &&
           z3::implies(!eout(t), flag(t) && bad_waiting == 0);
  }

 private:
  struct StepTerms {
    z3::expr eq, early, stale;
  };

  z3::expr flag(int t) { return c_.bool_const(fmt::format("flag@{}", t).c_str()); }
  z3::expr eout(int t) { return c_.bool_const(fmt::format("env_out@{}", t).c_str()); }
  z3::expr count(int t, int k) { return c_.int_const(fmt::format("count_{}@{}", k, t).c_str()); }

  const StepTerms& step(int t) {
    while (static_cast<int>(steps_.size()) <= t) steps_.push_back(make_step(static_cast<int>(steps_.size())));
    return steps_[static_cast<std::size_t>(t)];
  }

  StepTerms make_step(int t) {
    Translator tr(*session_, RealTheory::real, false);
    CounterSystem sys{*this, tr, t, c_.bool_val(true), c_.bool_val(false), {}, false};
    // spec's master_step, Jacobi: the Environment reads the counts as of the step's start.
    exploration::master_step(exploration::Mode::cosim, sys);
    z3::expr eq = sys.eq;
    std::vector<z3::expr> inflow(kClasses, c_.int_val(0));
    z3::expr early = c_.int_val(0), stale = c_.int_val(0);
    for (const Flow& fl : sys.flows) {
      // The ghosts after the step, with and without a plan.
      const int to_plan = class_index(fl.move.out, fl.move.driving, false, true);
      const int to_wait = class_index(fl.move.out, fl.move.driving, fl.reached_now, fl.fresh_kept);
      for (int q = 0; q < kClasses; ++q) {
        // Linear: a select of the flow or 0, never a product with a select.
        const z3::expr in = z3::ite(sys.plan, q == to_plan ? fl.f : c_.int_val(0), q == to_wait ? fl.f : c_.int_val(0));
        inflow[static_cast<std::size_t>(q)] = inflow[static_cast<std::size_t>(q)] + in;
      }
      if (!fl.reached_now) early = early + fl.f;
      if (fl.accept && !fl.from_fresh) stale = stale + fl.f;
    }
    for (int q = 0; q < kClasses; ++q) eq = eq && count(t + 1, q) == inflow[static_cast<std::size_t>(q)];
    return {eq && tr.side_conditions(), sys.plan && early > 0, stale > 0};
  }

  // A flow of `f` controllers of one class along one local step.
  struct Flow {
    z3::expr f;
    ControllerMove move;
    bool accept, reached_now, fresh_kept, from_fresh;
  };

  // The system master_step runs on the counts: controllers() are the counts, read by
  // environment_input below; robots_step moves them along the local steps of controller_rule;
  // environment_step is the spec's handshake_stage_rule.
  struct CounterSystem {
    CounterEncoding& enc;
    Translator& tr;
    int t;
    z3::expr eq = enc.c_.bool_val(true);
    z3::expr plan = enc.c_.bool_val(false);
    std::vector<Flow> flows;
    bool stepped = false;

    // Before robots_step: the counts at the step's start; after it (a master that reads the new
    // outputs): the controllers that moved to a lowered output.
    CountedControllers controllers() const {
      std::vector<z3::expr> lowered;
      if (stepped) {
        for (const Flow& fl : flows)
          if (!fl.move.out) lowered.push_back(fl.f);
      } else {
        for (int k = 0; k < kClasses; ++k)
          if (!class_of(k).out) lowered.push_back(enc.count(t, k));
      }
      if (lowered.empty()) lowered.push_back(enc.c_.int_val(0));
      return CountedControllers{lowered};
    }
    z3::expr environment_output() const { return enc.eout(t); }
    void robots_step(const z3::expr& env_output) {
      for (int k = 0; k < kClasses; ++k) {
        const LocalClass l = class_of(k);
        z3::expr out_of_k = enc.c_.int_val(0);
        for (int eo = 0; eo < 2; ++eo) {
          const auto& mv = enc.moves_[l.out ? 1 : 0][l.driving ? 1 : 0][static_cast<std::size_t>(eo)];
          for (std::size_t j = 0; j < mv.size(); ++j) {
            const z3::expr f = enc.c_.int_const(fmt::format("flow_{}_{}_{}@{}", k, eo, j, t).c_str());
            eq = eq && f >= 0 && z3::implies(env_output != enc.c_.bool_val(eo == 1), f == 0);
            out_of_k = out_of_k + f;
            const bool accept = l.out && !mv[j].out;
            flows.push_back({f, mv[j], accept, l.reached || mv[j].at, l.fresh && !accept, l.fresh});
          }
        }
        eq = eq && out_of_k == enc.count(t, k);
      }
      stepped = true;
    }
    void environment_step(const z3::expr& arrived) {
      // The master's reading, named as master_step's, is all_arrived over the counted controllers.
      const sym::Bool all = num::traced("exploration::master_step", sym::Bool::var(fmt::format("all@{}", t)));
      eq = eq && tr(all) == arrived;
      exploration::HandshakeStateT<S> hs{sym::Bool::var(fmt::format("flag@{}", t)), sym::Bool::var(fmt::format("env_out@{}", t))};
      plan = tr(exploration::handshake_stage_rule<S>(exploration::Mode::cosim, hs, all));
      eq = eq && enc.flag(t + 1) == tr(hs.flag) && enc.eout(t + 1) == tr(hs.output);
    }
    void place_bodies_on_waypoints() {}
  };

  Session* session_;
  z3::context& c_;
  const MoveTable& moves_;
  z3::expr n_;
  std::vector<StepTerms> steps_;
};

Outcome run_counter(Session& session) {
  if (auto o = handshake::all_arrived_lemma(session)) return *o;
  MoveTable moves;
  if (!enumerate_moves(session, moves))
    return {Verdict::unknown, "z3 gave up enumerating the controller's local steps", {}};
  CounterEncoding enc(session, moves);
  const KInductionResult r = k_induction(session, enc, 4, "counter");
  if (r.verdict == Verdict::proved)
    return {Verdict::proved,
            fmt::format("unsat: k-induction on the counter abstraction closed at k = {}, for every number of robots", r.k),
            {}};
  if (r.verdict == Verdict::refuted)
    return {Verdict::unknown,
            fmt::format("sat at depth {} of the counter abstraction: the property or the lemma fails for some number of "
                        "robots (handshake-safety gives a concrete trace for 1..8 robots)", r.depth),
            {}};
  return {Verdict::unknown,
          fmt::format("k-induction on the counter abstraction: no verdict within k = 4 (last query {}: {})",
                      session.queries().back().label, session.queries().back().answer),
          {}};
}

}  // namespace

std::vector<Obligation> handshake_counter_obligations() {
  return {Obligation{
      "handshake-safety-any-robots",
      "Under the Jacobi master with the spec's controller side, no-early-plan and fresh-acceptance hold for every "
      "number of robots.",
      Verdict::proved,
      {"counter abstraction of identical controllers: a state is the Environment's (flag, output) and the number of "
       "controllers in each local class (output, maneuver, reached, fresh); the number of robots is a free integer >= 1",
       "the local steps are enumerated by Z3 from the spec's controller_rule, each controller with its own free pose, "
       "heading, waypoint and tolerances (so the tolerances are not shared: more behaviours than a real run)",
       "a step is spec's master_step (Jacobi: the Environment reads the counts as of the step's start) on the counts: "
       "environment_input of counted controllers is \"no lowered output\", which all-arrived-any-robots proves "
       "all_arrived_rule is for every number of controllers (its queries run first here); the Environment plans "
       "through handshake_stage_rule (environment_handshake_rule)",
       "k-induction with the counting form of the hand-derived lemma; a counterexample of the abstraction is "
       "reported unknown (handshake-safety gives concrete traces)"},
      run_counter,
      [] { return handshake::step_quantities(handshake::Variant{}); }}};
}

}  // namespace swarmcheck::proofs
