// Obligation occupancy: one planning step of the fixed rule sets keeps every robot in the map,
// off obstacles, and in its own cell. Proved in two parts (occupancy.hpp): the choice lemma
// about the spec's choose_rule (interpreted symbolically, a counterexample replayed through the
// executed choose()), and the planning step built on any choice the lemma allows.
#include "proofs/obligations/occupancy.hpp"

#include <array>
#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {
namespace occupancy {

constexpr unsigned kIndexBits = 8;   // window indices and counts: s_range <= 3 has 48 candidates

std::vector<exploration::SymbolicCandidate> symbolic_window(int s_range, const std::string& prefix) {
  std::vector<exploration::SymbolicCandidate> out;
  const int side = 2 * s_range + 1;
  for (int k = 0; k < side * side - 1; ++k)
    out.push_back({sym::Real::var(fmt::format("{}_tau_{}", prefix, k)), sym::Bool::var(fmt::format("{}_blocked_{}", prefix, k)),
                   sym::Bool::var(fmt::format("{}_present_{}", prefix, k))});
  return out;
}

ChoiceQuery choice_query(Translator& t, const exploration::RuleDescriptor& rules,
                         const std::vector<exploration::SymbolicCandidate>& cands) {
  z3::context& c = t.ctx();
  // phi = 1: a key is the pheromone, already any real (pow of a free value adds nothing).
  const exploration::ChoiceTermsT<num::Symbolic> terms{sym::Real(1.0), sym::Real::var("eta_term"),
                                                       sym::Real::var("thesis_best_start")};
  const exploration::ChoiceT<num::Symbolic> ch =
      exploration::choose_rule<num::Symbolic>(rules, terms, cands, exploration::SymbolicDrawSite{"robot"});
  const z3::expr target = t(ch.target);
  z3::expr ok = target == c.bv_val(-1, kIndexBits);
  for (std::size_t k = 0; k < cands.size(); ++k)
    ok = ok || (target == c.bv_val(static_cast<int>(k), kIndexBits) && t(cands[k].present) && !t(cands[k].blocked));
  return {target, !ok};
}

}  // namespace occupancy

namespace {

using S = num::Symbolic;
constexpr int kMaxRange = 3;
constexpr std::array<exploration::RuleSet, 2> kRuleSets{exploration::RuleSet::deterministic,
                                                        exploration::RuleSet::stochastic};

struct Check {
  z3::check_result result;
  std::string detail;
};

// Replays a choice counterexample through the executed choose(): the model's present
// candidates, in order. The stochastic rules draw from seeds 0..999 (the model's draws are free
// choices): confirmed when one seed sends the robot to a blocked candidate.
bool replay_choice(const z3::model& m, Translator& t, const exploration::RuleDescriptor& rules,
                   const std::vector<exploration::SymbolicCandidate>& cands, std::string& detail) {
  std::vector<exploration::Candidate> concrete;
  std::vector<std::size_t> slot;
  for (std::size_t k = 0; k < cands.size(); ++k) {
    if (!m.eval(t(cands[k].present), true).is_true()) continue;
    concrete.push_back({{0, static_cast<int32_t>(k)}, model_double(m, t(cands[k].tau)),
                        m.eval(t(cands[k].blocked), true).is_true()});
    slot.push_back(k);
  }
  const exploration::ChoiceTerms terms{1.0, model_double(m, m.ctx().real_const("eta_term")),
                                       model_double(m, m.ctx().real_const("thesis_best_start"))};
  const bool draws = rules.best == exploration::BestRule::uniform_minimum ||
                     rules.fallback == exploration::FallbackRule::uniform_free;
  for (uint64_t seed = 0; seed < (draws ? 1000U : 1U); ++seed) {
    const exploration::Choice ch = exploration::choose(rules, terms, concrete, exploration::DrawSite{seed, 0, 0});
    if (ch.target >= 0 && concrete[static_cast<std::size_t>(ch.target)].blocked) {
      std::size_t blocked = 0;
      for (const auto& x : concrete) blocked += x.blocked ? 1 : 0;
      detail = fmt::format("{} candidates ({} blocked): choose() sends the robot to candidate {} of the window, "
                           "which is blocked (seed {}; confirmed by running choose())",
                           concrete.size(), blocked, slot[static_cast<std::size_t>(ch.target)], seed);
      return true;
    }
  }
  return false;
}

Check check_choice(Session& session, exploration::RuleSet set, int s_range) {
  const exploration::RuleDescriptor& rules = exploration::rules_of(set);
  Translator t(session.ctx(), RealTheory::real, false, occupancy::kIndexBits);
  const auto cands = occupancy::symbolic_window(s_range, "c");
  const occupancy::ChoiceQuery q = occupancy::choice_query(t, rules, cands);
  z3::solver s = session.make_preprocessed_solver();
  s.add(t.side_conditions());
  s.add(q.violates);
  const std::string label = fmt::format("choice-{}-s{}", rules.name, s_range);
  const z3::check_result r = session.check_preprocessed(s, label);
  if (r != z3::sat) return {r, ""};
  std::string detail;
  const bool confirmed = replay_choice(s.get_model(), t, rules, cands, detail);
  return {confirmed ? z3::sat : z3::unknown,
          confirmed ? label + ": " + detail : label + ": NOT reproduced by the executed choose(): a spurious counterexample"};
}

struct Cell {
  z3::expr i, j;
};

z3::expr in_map(const Cell& x, const z3::expr& n) { return x.i >= 0 && x.j >= 0 && x.i < n && x.j < n; }
z3::expr same(const Cell& a, const Cell& b) { return a.i == b.i && a.j == b.j; }

// One robot's move in the planning step, for any number of robots: the mover, at a cell of a
// symbolic map with free obstacles, takes any target the choice lemma allows, with one other
// robot standing for every other (occupancy is pairwise: if the step keeps the mover in the map,
// off obstacles and apart from any one other robot, it keeps it apart from all of them, and
// robots moving one after another in index order keep the invariant, whatever their number).
z3::check_result check_move(Session& session, int s_range) {
  z3::context& c = session.ctx();
  z3::solver s = session.make_solver();
  const z3::expr n = c.int_const("map_size");
  const z3::sort I = c.int_sort();
  const z3::func_decl obstacle = c.function("obstacle", I, I, c.bool_sort());
  const Cell here{c.int_const("i"), c.int_const("j")}, other{c.int_const("other_i"), c.int_const("other_j")};
  auto fine = [&](const Cell& x) { return in_map(x, n) && !obstacle(x.i, x.j); };
  s.add(n >= 1 && fine(here) && fine(other) && !same(here, other));
  const z3::expr target = c.int_const("target");
  z3::expr allowed = target == -1;
  z3::expr ni = here.i, nj = here.j;
  int k = 0;
  for (int di = -s_range; di <= s_range; ++di)
    for (int dj = -s_range; dj <= s_range; ++dj) {
      if (di == 0 && dj == 0) continue;
      const Cell x{here.i + di, here.j + dj};
      allowed = allowed || (target == k && in_map(x, n) && !(obstacle(x.i, x.j) || same(other, x)));
      ni = z3::ite(target == k, x.i, ni);
      nj = z3::ite(target == k, x.j, nj);
      ++k;
    }
  s.add(allowed);
  const Cell moved{c.int_const("i_after"), c.int_const("j_after")};
  s.add(moved.i == ni && moved.j == nj);
  s.add(!(fine(moved) && !same(moved, other)));
  return session.check(s, fmt::format("move-s{}", s_range));
}

Outcome run_occupancy(Session& session) {
  for (int s_range = 1; s_range <= kMaxRange; ++s_range)
    for (exploration::RuleSet set : kRuleSets) {
      const Check r = check_choice(session, set, s_range);
      if (r.result == z3::sat) return {Verdict::refuted, "sat: " + r.detail, {}};
      if (r.result != z3::unsat)
        return {Verdict::unknown, r.detail.empty() ? "unknown on query " + session.queries().back().label : r.detail, {}};
    }
  for (int s_range = 1; s_range <= kMaxRange; ++s_range) {
    {
      const z3::check_result r = check_move(session, s_range);
      if (r == z3::sat)
        return {Verdict::unknown,
                "sat on query " + session.queries().back().label +
                    ": the planning step breaks occupancy with choices the lemma allows (the composition, not the rule)",
                {}};
      if (r != z3::unsat) return {Verdict::unknown, "unknown on query " + session.queries().back().label, {}};
    }
  }
  return {Verdict::proved,
          fmt::format("unsat: the choice lemma (deterministic and stochastic, s_range 1..{}) and one robot's move "
                      "(s_range 1..{}), so every number of robots; {} queries",
                      kMaxRange, kMaxRange, session.queries().size()),
          {}};
}

}  // namespace

std::vector<Obligation> occupancy_obligations() {
  return {Obligation{
      "occupancy",
      "One planning step of the deterministic or stochastic rule set, from a state with every "
      "robot in the map, off obstacles and alone in its cell, keeps all three.",
      Verdict::proved,
      {"the choice lemma: the spec's choose_rule interpreted symbolically over a window of any contents "
       "(each cell present or not, blocked or not, any pheromone; phi = 1 so a key is the pheromone); the "
       "stochastic rules' draws are free choices in their ranges; indices as 8-bit integers",
       "the planning step: map size, obstacle map and robot cells symbolic; robots decide in index order "
       "and see earlier robots' moves at once, each choosing any target the lemma allows; proved for one "
       "mover and one other robot, which covers any number of robots (occupancy is pairwise)",
       "s_range 1..3",
       "a counterexample counts only when the executed choose() reproduces it (stochastic rules: with "
       "one of the seeds 0..999)"},
      run_occupancy,
      {"exploration::choose_rule", "exploration::pheromone_key_rule"}}};
}

}  // namespace swarmcheck::proofs
