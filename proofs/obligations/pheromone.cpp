// Obligation pheromone-bounds: every cell's pheromone stays within
//   0 <= tau <= B = R (max_ph + epsilon / a2) / min(1, ertu dt)
// whenever ertu dt > 0, R the number of robots whose deposit windows cover the cell, for every R
// and every age of a cell's value. The bound is stated over the parameters (1 - min(1, ertu dt)
// is the decay a correct factor gives), not over the code's factor, so a wrong factor is caught.
//
// The step runs: evaporation (the grid reads a value written k ticks ago through
// decayed_pheromone_rule(value, decay_factor(table, k)), or the thesis's update every tick), then
// the deposit stage (IndexOrder::deposit: deposit_around each robot's centre, window_around,
// deposit_amount_at_rule, deposited_pheromone_rule). The queries, over the reals:
//   decay table    each entry of make_decay_table_rule(f), as the code computes it from the entry
//                  before (that one replaced by any q in [0, f]), is in [0, f]: every entry, by
//                  induction over the table's loop
//   decay factor   each multiplication of decay_factor's loop (the product so far replaced by any
//                  a in [0, 1], the entries any values in [0, f]) is in [0, f]; F(0) = 1: every
//                  age, by induction over the loop (impl's LazyGrid continues F with the same loop)
//   amounts        every amount deposit_amount_at_rule gives within s_range 3 is in
//                  [0, max_ph + epsilon / a2]
//   deposit stage  one robot's deposit_around adds to any cell at most one amount (s_range 1..3;
//                  the amounts by the lemma above): every number of robots, by induction over
//                  IndexOrder::deposit's loop
//   consecution    a value within B, aged by any factor in [0, f] (or the thesis's update), plus
//                  R such amounts, is within B; from an empty map, R amounts are
//   whole steps    the spec's environment_stages (plan, evaporate, deposit) of 1 robot from the
//                  step's entry point, both evaporations, on a symbolic map (the decay factor, the
//                  amounts and the choice by their lemmas)
// A counterexample is replayed by running the executed stages from an empty map (environment_
// stages with robots standing still on the cell, evaporation_factor_rule, make_decay_table_rule,
// decay_factor, deposit_around, on a concrete grid): confirmed when the pheromone leaves the bound.
#include <cmath>
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <unordered_set>

#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/occupancy.hpp"
#include "proofs/obligations/replay_grid.hpp"
#include "proofs/obligations/symbolic_world.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/decay.hpp"
#include "spec/exploration/deposit.hpp"
#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::proofs {
namespace {

using S = num::Symbolic;
using C = num::Concrete;
constexpr int kMaxRange = 3;

// The algorithm's parameters as the symbolic world names them.
struct Parameters {
  sym::Real ertu = sym::Real::var("ertu"), dt = sym::Real::var("step_size"), max_ph = sym::Real::var("max_ph"),
            epsilon = sym::Real::var("epsilon"), a1 = sym::Real::var("a1"), a2 = sym::Real::var("a2");
  sym::Real f() const { return exploration::evaporation_factor_rule<S>(ertu, dt); }
  sym::Real amount_bound() const { return max_ph + epsilon / a2; }   // the most one deposit leaves
};

// The parameters' domains (SPEC.md section 1), decay present (ertu dt > 0).
z3::expr domains(Translator& t, const Parameters& p) {
  return t(p.ertu) >= 0 && t(p.dt) > 0 && t(p.ertu) * t(p.dt) > 0 && t(p.max_ph) >= 0 && t(p.epsilon) >= 0 &&
         t(p.a1) > 0 && t(p.a2) > 0;
}

// The decay lemmas mention no deposit parameter, so asking them with a positive max_ph changes
// no verdict; it makes a counterexample's deposits non-zero, so that the replay from an empty map
// has pheromone for the faulty decay to keep (with max_ph = epsilon = 0 every bound is 0 and met).
z3::expr deposits_visible(Translator& t, const Parameters& p) { return t(p.max_ph) > 0; }

// B for R robots: bound * min(1, ertu dt) = R (max_ph + epsilon / a2), division-free for nlsat.
z3::expr bound_of(Translator& t, const Parameters& p, const z3::expr& robots, const z3::expr& bound) {
  const z3::expr c = t(p.ertu) * t(p.dt);
  return bound * z3::ite(c < 1, c, t.ctx().real_val(1)) == robots * t(p.amount_bound());
}

struct Model {
  exploration::Params params = exploration::default_params();
  std::string text() const {
    return fmt::format("ertu = {:.6g}, step_size = {:.6g}, max_ph = {:.6g}, epsilon = {:.6g}, a1 = {:.6g}, a2 = {:.6g}",
                       params.ertu, params.step_size, params.max_ph, params.epsilon, params.a1, params.a2);
  }
};

Model model_of(const z3::model& m, Translator& t, const Parameters& p) {
  Model out;
  auto d = [&](const sym::Real& x) { return model_double(m, t(x)); };
  out.params.ertu = d(p.ertu);
  out.params.step_size = d(p.dt);
  out.params.max_ph = d(p.max_ph);
  out.params.epsilon = d(p.epsilon);
  out.params.a1 = d(p.a1);
  out.params.a2 = d(p.a2);
  return out;
}

// The replay: stages that plan nothing (the robots stand still on the cell, as walled-in robots
// do) and deposit as the spec does.
struct StandStill {
  int64_t plan(const exploration::EnvironmentConfig&, exploration::EnvironmentState&, ReplayGrid&) const { return 0; }
  void deposit(const exploration::EnvironmentConfig& cfg, const exploration::EnvironmentState& env, ReplayGrid& g) const {
    exploration::IndexOrder{}.deposit(cfg, env, g);
  }
};

// Runs the executed stages from an empty map with these parameters: `robots` robots standing on
// cell (di, dj) away from the watched cell, depositing every `period` ticks, for at most 20000
// ticks. Returns the first tick at which the watched cell leaves [0, B] (B with a relative slack
// of 1e-9 for rounding, so only a real excess counts), and the value then.
std::optional<std::pair<int64_t, double>> run_from_empty(const exploration::Params& params, exploration::RuleSet rule,
                                                        int robots, int32_t di, int32_t dj, int period, double& bound) {
  exploration::Scenario sc = exploration::default_scenario();
  sc.map_size = 64;
  sc.rule = rule;
  sc.params = params;
  sc.params.s_range = std::max(std::abs(di), std::abs(dj));
  if (sc.params.s_range == 0) sc.params.s_range = 1;
  // make_environment_config's checks (f in [0, 1]) would stop a faulty factor before it runs:
  // the replay builds the config from the rules the checks guard.
  exploration::EnvironmentConfig cfg{sc,
                                     &exploration::rules_of(rule),
                                     exploration::choice_terms(sc.params),
                                     exploration::DepositKernel(sc.params, sc.map_size),
                                     exploration::make_decay_table_rule<C>(
                                         exploration::evaporation_factor_rule<C>(params.ertu, params.step_size)),
                                     params.ertu * params.step_size};
  const exploration::CellIndex watched{32, 32}, at{32 + di, 32 + dj};
  exploration::EnvironmentState env;
  env.progress.free_cells = 1;
  for (int r = 0; r < robots; ++r) {
    env.robots.push_back({at, exploration::centre_of(at, 1.0)});
    env.deposit_centre.push_back(at);
  }
  ReplayGrid grid(cfg, 0);
  bound = robots * (params.max_ph + params.epsilon / params.a2) / std::min(1.0, params.ertu * params.step_size);
  const double slack = std::max(1e-300, std::fabs(bound) * 1e-9);
  exploration::IndexOrder{}.deposit(cfg, env, grid);   // initialisation: every robot deposits once
  for (int64_t t = 0; t <= 20000; ++t) {
    if (t > 0) exploration::environment_stages(cfg, env, grid, t % period == 0, StandStill{});
    const double v = grid.pheromone(watched, env.tick);
    if (!(v >= 0) || v > bound + slack) return std::make_pair(env.tick, v);
  }
  return std::nullopt;
}

// Confirms a counterexample's parameters by runs from an empty map: 1..robots robots on the cell
// or next to it, depositing every 1..4 ticks, under the rule set's evaporation.
std::optional<std::string> replay(const Model& m, exploration::RuleSet rule, int robots) {
  for (int r = 1; r <= robots; ++r)
    for (int period = 1; period <= 4; ++period)
      for (int32_t d = 0; d <= 1; ++d) {
        double bound = 0;
        if (const auto hit = run_from_empty(m.params, rule, r, d, 0, period, bound))
          return fmt::format("{}: {} robot(s) at distance {} depositing every {} tick(s) under the {} rule set: at tick "
                             "{} the cell holds {:.6g} against the bound {:.6g} (confirmed by running the executed "
                             "stages from an empty map)",
                             m.text(), r, d, period, exploration::rules_of(rule).name, hit->first, hit->second, bound);
      }
  return std::nullopt;
}

struct Check {
  z3::check_result result;
  std::string detail;
};

// A satisfiable query's verdict: confirmed by a replay, else a spurious counterexample.
Check settle(const z3::model& m, Translator& t, const Parameters& p, const std::string& label,
             exploration::RuleSet rule, int robots) {
  const Model mo = model_of(m, t, p);
  if (const auto hit = replay(mo, rule, robots)) return {z3::sat, label + ": " + *hit};
  return {z3::unknown, label + ": " + mo.text() +
                           ": NOT reproduced by the executed stages from an empty map: a spurious counterexample"};
}

// The nearest calls named fn under a node, not looking inside them.
void nearest_calls(const sym::NodePtr& n, std::string_view fn, std::vector<sym::NodePtr>& out,
                   std::unordered_set<const sym::Node*>& seen) {
  for (const sym::NodePtr& a : n->args) {
    if (!seen.insert(a.get()).second) continue;
    if (a->op == sym::Op::call && a->name == fn) out.push_back(a);
    else nearest_calls(a, fn, out, seen);
  }
}

// Induction over a loop the code unrolls: each call node of fn under `root` (a pass of the
// loop), with the nearest earlier passes replaced by fresh reals satisfying `assumed`, must
// satisfy `holds`. Identical steps (the same Z3 term after the replacement) are asked once.
Check loop_induction(Session& session, Translator& t, const sym::NodePtr& root, std::string_view fn,
                     const z3::expr& context, const std::function<z3::expr(const z3::expr&)>& assumed,
                     const std::function<z3::expr(const z3::expr&)>& holds, const std::string& label,
                     const std::function<Check(const z3::model&)>& on_sat) {
  const bool fp = t.theory() == RealTheory::fp64;
  std::unordered_set<unsigned> asked;
  std::vector<z3::expr> kept;
  for (const sym::NodePtr& pass : sym::calls_of({root}, fn)) {
    int fresh = 0;   // the same names in every pass: identical passes give identical terms
    std::vector<sym::NodePtr> earlier;
    std::unordered_set<const sym::Node*> seen;
    nearest_calls(pass, fn, earlier, seen);
    z3::expr_vector from(t.ctx()), to(t.ctx());
    z3::expr assumptions = t.ctx().bool_val(true);
    for (const sym::NodePtr& e : earlier) {
      const z3::expr q = t.variable(fmt::format("{}!earlier{}", label, fresh++), sym::Sort::real);
      from.push_back(t.node(e));
      to.push_back(q);
      assumptions = assumptions && assumed(q);
    }
    z3::expr step = t.node(pass);
    step = step.substitute(from, to);
    if (!asked.insert(step.id()).second) continue;
    kept.push_back(step);   // alive, so that an identical term later has the same id
    z3::solver s = fp ? session.make_solver() : session.make_nonlinear_solver();
    s.add(context && assumptions && t.side_conditions());
    s.add(!holds(step));
    const z3::check_result r = session.check(s, fmt::format("{}-{}", label, asked.size()));
    if (r == z3::sat) return on_sat(s.get_model());
    if (r != z3::unsat) return {r, ""};
  }
  return {z3::unsat, ""};
}

// The decay table: every entry from the one before, in [0, f].
Check check_table(Session& session) {
  Translator t(session, RealTheory::real);
  const Parameters p;
  const exploration::DecayTableT<S> table = exploration::make_decay_table_rule<S>(p.f());
  const z3::expr f = t(table.pow2[0]), zero = t.ctx().real_val(0), one = t.ctx().real_val(1);
  const z3::expr c = t(p.ertu) * t(p.dt);
  {  // P[0] = f is in [0, 1] and leaves the decay the bound needs: f + min(1, ertu dt) <= 1.
    z3::solver s = session.make_nonlinear_solver();
    s.add(domains(t, p) && deposits_visible(t, p) && t.side_conditions());
    s.add(!(zero <= f && f <= one && f + z3::ite(c < 1, c, one) <= one));
    const z3::check_result r = session.check(s, "decay-factor-f");
    if (r == z3::sat) return settle(s.get_model(), t, p, "decay-factor-f", exploration::RuleSet::deterministic, 1);
    if (r != z3::unsat) return {r, ""};
  }
  return loop_induction(
      session, t, table.pow2.back().node(), "exploration::make_decay_table",
      domains(t, p) && deposits_visible(t, p) && zero <= f && f <= one,
      [&](const z3::expr& q) { return zero <= q && q <= f; }, [&](const z3::expr& x) { return zero <= x && x <= f; },
      "decay-table", [&](const z3::model& m) {
        return settle(m, t, p, "decay-table", exploration::RuleSet::deterministic, 1);
      });
}

// The decay function: every multiplication of its loop in [0, f]; F(0) = 1; F(k) for k >= 1 is a
// multiplication of the loop (never the initial 1).
Check check_factor(Session& session) {
  Translator t(session, RealTheory::real);
  const Parameters p;
  exploration::DecayTableT<S> table;
  for (std::size_t i = 0; i < table.pow2.size(); ++i) table.pow2[i] = sym::Real::var(fmt::format("P_{}", i));
  const z3::expr f = t(p.f()), zero = t.ctx().real_val(0), one = t.ctx().real_val(1);
  z3::expr entries = domains(t, p) && deposits_visible(t, p) && zero <= f && f <= one;
  for (const sym::Real& e : table.pow2) entries = entries && zero <= t(e) && t(e) <= f;
  const sym::Real f0 = exploration::decay_factor_rule<S>(table, 0);
  if (!(f0.is_literal() && f0.literal() == 1.0))
    return {z3::sat, "decay-factor: F(0) is not 1: a value read at its write tick is not the value written"};
  constexpr int64_t kAll = INT64_MAX;   // every bit: every pass of the loop
  for (const int64_t k : {int64_t{1}, int64_t{2}, int64_t{3}, kAll, int64_t{0x5555555555555555}, kAll ^ 0x5555555555555555}) {
    const sym::Real fk = exploration::decay_factor_rule<S>(table, k);
    const std::string label = fmt::format("decay-factor-k{:x}", k);
    if (fk.is_literal() || !(fk.node()->op == sym::Op::call && fk.node()->name == "exploration::decay_factor")) {
      // Not a multiplication of the loop: F(k) itself must be in [0, f].
      z3::solver s = session.make_nonlinear_solver();
      s.add(entries && t.side_conditions());
      s.add(!(zero <= t(fk) && t(fk) <= f));
      const z3::check_result r = session.check(s, label);
      if (r == z3::sat) return settle(s.get_model(), t, p, label, exploration::RuleSet::deterministic, 1);
      if (r != z3::unsat) return {r, ""};
      continue;
    }
    const Check c = loop_induction(
        session, t, fk.node(), "exploration::decay_factor", entries, [&](const z3::expr& a) { return zero <= a && a <= one; },
        [&](const z3::expr& x) { return zero <= x && x <= f; }, label,
        [&](const z3::model& m) { return settle(m, t, p, label, exploration::RuleSet::deterministic, 1); });
    if (c.result != z3::unsat) return c;
  }
  return {z3::unsat, ""};
}

// Every amount the deposit kernel leaves within s_range 3 of the centre is in
// [0, max_ph + epsilon / a2] (deposit_amount_at_rule at each offset).
Check check_amounts(Session& session) {
  Translator t(session, RealTheory::real, false);
  const Parameters p;
  const exploration::DepositParamsT<S> dp{p.max_ph, p.a1, p.epsilon, p.a2};
  const z3::expr a = t(p.amount_bound()), zero = t.ctx().real_val(0);
  z3::expr all = t.ctx().bool_val(true);
  for (int32_t di = 0; di <= kMaxRange; ++di)
    for (int32_t dj = 0; dj <= di; ++dj) {   // the distance is symmetric in the offsets
      const z3::expr x = t(exploration::deposit_amount_at_rule<S>(dp, di, dj));
      all = all && zero <= x && x <= a;
    }
  z3::solver s = session.make_nonlinear_solver();
  s.add(domains(t, p) && t.side_conditions());
  s.add(!all);
  const z3::check_result r = session.check(s, "deposit-amounts");
  if (r == z3::sat) return settle(s.get_model(), t, p, "deposit-amounts", exploration::RuleSet::deterministic, 1);
  return {r, ""};
}

// The contracts the lemmas above prove, for queries that use them in place of the functions.
void use_lemmas(Translator& t, const Parameters& p) {
  const z3::expr a = t(p.amount_bound()), f = t(p.f()), zero = t.ctx().real_val(0);
  t.abstract_call("exploration::deposit_amount_rule", [a, zero](const z3::expr& x) { return zero <= x && x <= a; });
  t.abstract_call("exploration::decay_factor", [f, zero](const z3::expr& x) { return zero <= x && x <= f; });
}

// The deposit stage's pass for one robot: deposit_around on a symbolic map adds to any cell X at
// most one amount, in [0, max_ph + epsilon / a2] (each amount by the lemma above).
Check check_deposit_pass(Session& session, int s_range) {
  Translator t(session, RealTheory::real, false);
  const Parameters p;
  use_lemmas(t, p);
  const world::Config cfg = world::symbolic_config(exploration::RuleSet::deterministic, s_range);
  world::Grid grid(cfg, "map", 1, 1);
  const world::Cell x{sym::Int::var("x_i"), sym::Int::var("x_j")}, centre{sym::Int::var("centre_i"), sym::Int::var("centre_j")};
  const sym::Real before = grid.pheromone(x, 1);
  exploration::deposit_around(cfg, grid, centre, 1);
  const z3::expr v = t(before), after = t(grid.pheromone(x, 1)), a = t(p.amount_bound());
  z3::solver s = session.make_smt_solver();
  s.add(domains(t, p) && t(cfg.scenario.map_size) >= 1 && t.side_conditions());
  s.add(!(v <= after && after <= v + a));
  const std::string label = fmt::format("deposit-pass-s{}", s_range);
  const z3::check_result r = session.check_smt(s, label);
  if (r == z3::sat) return settle(s.get_model(), t, p, label, exploration::RuleSet::deterministic, 1);
  return {r, ""};
}

// Consecution for every R and every age: a value within B, aged by any factor in [0, f] (the
// decay lemmas) or by the thesis's update, plus R amounts of at most max_ph + epsilon / a2 (the
// deposit pass, R times), is within B; and from an empty map R amounts are.
Check check_consecution(Session& session, exploration::Evaporation ev) {
  Translator t(session, RealTheory::real);
  const Parameters p;
  z3::context& c = t.ctx();
  const sym::Real v = sym::Real::var("tau"), factor = sym::Real::var("F");
  const sym::Real aged = ev == exploration::Evaporation::decay_function
                             ? exploration::decayed_pheromone_rule<S>(v, factor)
                             : exploration::thesis_evaporate_rule<S>(v, p.ertu * p.dt);
  const z3::expr robots = c.real_const("R"), bound = c.real_const("bound"), zero = c.real_val(0), f = t(p.f());
  const z3::expr deposits = robots * t(p.amount_bound());
  const std::string label = ev == exploration::Evaporation::decay_function ? "step-decay" : "step-thesis";
  for (const bool init : {true, false}) {
    z3::solver s = session.make_nonlinear_solver();
    s.add(domains(t, p) && robots >= 1 && bound_of(t, p, robots, bound) && t.side_conditions());
    if (init) {
      s.add(!(zero <= deposits && deposits <= bound));
    } else {
      s.add(zero <= t(v) && t(v) <= bound && zero <= t(factor) && t(factor) <= f);
      s.add(!(zero <= t(aged) && t(aged) + deposits <= bound));
    }
    const std::string l = init ? "init" : label;
    const z3::check_result r = session.check(s, l);
    if (r == z3::sat) {
      const exploration::RuleSet rule = ev == exploration::Evaporation::decay_function ? exploration::RuleSet::deterministic
                                                                                       : exploration::RuleSet::thesis;
      return settle(s.get_model(), t, p, l, rule, 3);
    }
    if (r != z3::unsat) return {r, ""};
  }
  return {z3::unsat, ""};
}

// A whole step from its entry point: environment_stages (plan, evaporate, deposit) of one robot
// on a symbolic map whose cell X holds a value within B (R = 1) written `age` ticks ago.
Check check_whole_step(Session& session, exploration::RuleSet rule, bool planning, int64_t age, int robots = 1,
                       world::ChoiceMode choice = world::ChoiceMode::any_free) {
  Translator t(session, RealTheory::real, false);
  const Parameters p;
  use_lemmas(t, p);
  // By default the robots choose any candidates the choice lemma (any_free, below) allows: the
  // bound holds wherever they deposit, and the query need not unroll the choice.
  const world::Config cfg = world::symbolic_config(rule, 1, choice);
  // The map's values were written `age` ticks before the step's end (age - 1 before it); with the
  // spec's own choice, at the step's tick (so the keys it compares are the values: linear).
  const int64_t written = choice == world::ChoiceMode::exact ? age : 0;
  world::Environment env = world::symbolic_environment(cfg, robots, "robot", written == 0 ? age - 1 : age);
  world::Grid grid(cfg, "map", env.tick, written);
  const world::Cell x{sym::Int::var("x_i"), sym::Int::var("x_j")};
  const z3::expr before = t(grid.stored(x));
  // The watched value evaporated by the step's end (what the consecution queries bound): the
  // grid reads the same expression, so the query need not redo their nonlinear arithmetic.
  const z3::expr evaporated = t(grid.aged(grid.stored(x), env.tick + 1 - grid.written()));
  exploration::environment_stages(cfg, env, grid, planning);
  const z3::expr after = t(grid.pheromone(x, env.tick));
  z3::context& c = t.ctx();
  const z3::expr bound = c.real_const("bound"), zero = c.real_val(0);
  // B stands for the bound; what it is (B min(1, ertu dt) = R (max_ph + epsilon / a2)) the
  // consecution queries use to bound the evaporated value, assumed here: what is left to show is
  // that the step adds at most R amounts to the watched cell, wherever the robots deposit.
  z3::solver s = session.make_solver();
  s.add(t(p.a2) > 0 && t(p.epsilon) >= 0 && t(p.max_ph) >= 0 && t(cfg.scenario.map_size) >= 1);
  s.add(zero <= before && before <= bound && t.side_conditions());
  s.add(zero <= evaporated && evaporated + c.real_val(robots) * t(p.amount_bound()) <= bound);
  s.add(!(zero <= after && after <= bound));
  const std::string label = fmt::format("whole-step-{}-{}-age{}-n{}{}", exploration::rules_of(rule).name,
                                        planning ? "plan" : "wait", age, robots,
                                        choice == world::ChoiceMode::exact ? "-exact" : "");
  const z3::check_result r = session.check(s, label);
  if (r == z3::sat) return settle(s.get_model(), t, p, label, rule, robots);
  return {r, ""};
}

Outcome run_pheromone(Session& session) {
  std::vector<std::function<Check()>> parts = {
      [&] { return check_table(session); },
      [&] { return check_factor(session); },
  };
  parts.push_back([&] { return check_amounts(session); });
  for (int s_range = 1; s_range <= kMaxRange; ++s_range) parts.push_back([&, s_range] { return check_deposit_pass(session, s_range); });
  for (auto ev : {exploration::Evaporation::decay_function, exploration::Evaporation::literal_per_step})
    parts.push_back([&, ev] { return check_consecution(session, ev); });
  std::optional<Outcome> lemma;
  parts.push_back([&] {
    lemma = occupancy::choice_lemma(session, exploration::RuleSet::deterministic, 1, true);
    return lemma ? Check{z3::unknown, "lemma"} : Check{z3::unsat, ""};
  });
  // Whole steps: the decay function without a plan (one robot) and with one (two robots, the
  // second one's choice reading the first one's grid effects, as the step runs them), values one
  // and two ticks old; the thesis's update (it writes every cell every tick) without a plan.
  for (const bool planning : {false, true})
    for (const int64_t age : {int64_t{1}, int64_t{2}})
      parts.push_back([&, planning, age] {
        return check_whole_step(session, exploration::RuleSet::deterministic, planning, age, planning ? 2 : 1);
      });
  parts.push_back([&] { return check_whole_step(session, exploration::RuleSet::thesis, false, 1); });
  for (const auto& part : parts) {
    const Check c = part();
    if (lemma) return *lemma;
    if (c.result == z3::sat) return {Verdict::refuted, "sat: " + c.detail, {}};
    if (c.result != z3::unsat)
      return {Verdict::unknown, c.detail.empty() ? "unknown on query " + session.queries().back().label : c.detail, {}};
  }
  return {Verdict::proved,
          fmt::format("unsat: the decay table (every entry) and factor (every age) by induction over their loops, the "
                      "deposit stage by induction over the robots (s_range 1..{}), consecution for every R, whole steps "
                      "of one and two robots from environment_stages; {} queries",
                      kMaxRange, session.queries().size()),
          {}};
}

// The watched cell's pheromone after a whole step of two robots (deterministic rule set,
// s_range 1): what the bound is about, from the step's entry point.
std::vector<sym::NodePtr> step_quantities(exploration::RuleSet rule) {
  const world::Config cfg = world::symbolic_config(rule, 1);
  world::Environment env = world::symbolic_environment(cfg, 2, "robot", 3);
  world::Grid grid(cfg, "map", 3, 0);
  const world::Cell x{sym::Int::var("x_i"), sym::Int::var("x_j")};
  exploration::environment_stages(cfg, env, grid, true);
  return {grid.pheromone(x, env.tick).node()};
}

}  // namespace

std::vector<Obligation> pheromone_obligations() {
  return {Obligation{
      "pheromone-bounds",
      "Every cell's pheromone stays within 0 <= tau <= R (max_ph + epsilon / a2) / min(1, ertu dt) whenever ertu dt > 0, "
      "R the number of robots whose deposit windows cover the cell, for every R and every age of a cell's value.",
      Verdict::proved,
      {"over the reals: rounding is not modelled (over IEEE doubles even the decay table's one-multiplication step, "
       "fl(q q) <= f for q <= f <= 1, takes Z3 about 45 s of bit-blasting, outside prove's budget); a counterexample "
       "counts only when running the executed stages from an empty map with its parameters leaves the bound",
       "the step's functions, interpreted symbolically: evaporation_factor_rule, make_decay_table_rule and decay_factor "
       "(their loops by induction: every entry, every age; the library's LazyGrid continues F with the same loop), "
       "decayed_pheromone_rule or thesis_evaporate_rule (the grids' read), deposit_around over window_around with "
       "deposit_amount_at_rule and deposited_pheromone_rule (one robot's pass, s_range 1..3; every number of robots by "
       "induction over IndexOrder::deposit), and whole steps of one robot from environment_stages (plan, evaporate, "
       "deposit; one and two robots, the decay function and the thesis's update) on a symbolic map, the robots choosing "
       "any candidates the choice lemma allows (choose_rule's target is a present free candidate or none: proved here "
       "for the deterministic rule set, s_range 1)",
       "exp is uninterpreted: positive, at most 1 for a non-positive argument; a quotient by a term is a fresh real q "
       "with q b = a",
       "parameters free in their SPEC.md domains with ertu dt > 0; R any real >= 1"},
      run_pheromone,
      [] {
        std::vector<sym::NodePtr> out = step_quantities(exploration::RuleSet::deterministic);
        for (const sym::NodePtr& n : step_quantities(exploration::RuleSet::thesis)) out.push_back(n);
        return out;
      }}};
}

}  // namespace swarmcheck::proofs
