// Obligation occupancy: one planning step of the fixed rule sets, robots in index order with
// occupancy updated at once, keeps every robot in the map, off obstacles, and in its own cell.
#include "proofs/obligations/occupancy.hpp"

#include <fmt/format.h>

#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {
namespace occupancy {

z3::expr deterministic_target(z3::context& c, const std::vector<SymCandidate>& cands) {
  // Scan: a valid candidate becomes best when there is none yet or key <= best key.
  z3::expr has = c.bool_val(false), best = c.int_val(-1), best_key = c.real_val(0),
           best_blocked = c.bool_val(false);
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const z3::expr take = cands[k].valid && (!has || cands[k].key <= best_key);
    best = z3::ite(take, c.int_val(static_cast<int>(k)), best);
    best_key = z3::ite(take, cands[k].key, best_key);
    best_blocked = z3::ite(take, cands[k].blocked, best_blocked);
    has = has || cands[k].valid;
  }
  z3::expr first_free = c.int_val(-1);   // built backwards: the first free one wins
  for (std::size_t k = cands.size(); k-- > 0;)
    first_free = z3::ite(cands[k].valid && !cands[k].blocked, c.int_val(static_cast<int>(k)), first_free);
  return z3::ite(!has, c.int_val(-1), z3::ite(!best_blocked, best, first_free));
}

z3::expr stochastic_target(z3::context& c, z3::solver& s, const std::vector<SymCandidate>& cands,
                           const z3::expr& tie, const z3::expr& fallback) {
  z3::expr any_valid = c.bool_val(false), any_free = c.bool_val(false);
  for (const SymCandidate& x : cands) {
    any_valid = any_valid || x.valid;
    any_free = any_free || (x.valid && !x.blocked);
  }
  z3::expr tie_blocked = c.bool_val(false);
  for (std::size_t k = 0; k < cands.size(); ++k) {
    const z3::expr is_tie = tie == c.int_val(static_cast<int>(k));
    z3::expr minimal = cands[k].valid;
    for (const SymCandidate& y : cands) minimal = minimal && z3::implies(y.valid, cands[k].key <= y.key);
    s.add(z3::implies(is_tie && any_valid, minimal));
    s.add(z3::implies(fallback == c.int_val(static_cast<int>(k)) && any_free, cands[k].valid && !cands[k].blocked));
    tie_blocked = z3::ite(is_tie, cands[k].blocked, tie_blocked);
  }
  const int n = static_cast<int>(cands.size());
  s.add(tie >= 0 && tie < n && fallback >= 0 && fallback < n);
  return z3::ite(!any_valid, c.int_val(-1), z3::ite(!tie_blocked, tie, z3::ite(any_free, fallback, c.int_val(-1))));
}

}  // namespace occupancy

namespace {

using occupancy::SymCandidate;
constexpr int kMaxRobots = 6;

struct Cell {
  z3::expr i, j;
};

z3::expr in_map(const Cell& x, const z3::expr& n) { return x.i >= 0 && x.j >= 0 && x.i < n && x.j < n; }
z3::expr same(const Cell& a, const Cell& b) { return a.i == b.i && a.j == b.j; }

z3::check_result check(Session& session, int robots, bool stochastic) {
  z3::context& c = session.ctx();
  z3::solver s = session.make_solver();
  const z3::expr n = c.int_const("map_size");
  const z3::sort I = c.int_sort();
  const z3::func_decl obstacle = c.function("obstacle", I, I, c.bool_sort());
  const z3::func_decl key = c.function("key", I, I, c.real_sort());   // pow(tau, phi) per cell
  s.add(n >= 1);
  std::vector<Cell> pos;
  for (int r = 0; r < robots; ++r) {
    pos.push_back(Cell{c.int_const(fmt::format("i_{}", r).c_str()), c.int_const(fmt::format("j_{}", r).c_str())});
    s.add(in_map(pos.back(), n) && !obstacle(pos.back().i, pos.back().j));
    for (int q = 0; q < r; ++q) s.add(!same(pos[static_cast<std::size_t>(q)], pos.back()));
  }
  // Robots decide in index order; robot r sees robots < r already moved (s_range = 1).
  for (int r = 0; r < robots; ++r) {
    const Cell here = pos[static_cast<std::size_t>(r)];
    std::vector<Cell> cells;
    std::vector<SymCandidate> cands;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj) {
        if (di == 0 && dj == 0) continue;
        const Cell x{here.i + di, here.j + dj};
        z3::expr occupied = c.bool_val(false);
        for (int q = 0; q < robots; ++q)
          if (q != r) occupied = occupied || same(pos[static_cast<std::size_t>(q)], x);
        cells.push_back(x);
        cands.push_back(SymCandidate{in_map(x, n), key(x.i, x.j), obstacle(x.i, x.j) || occupied});
      }
    const z3::expr target =
        stochastic ? occupancy::stochastic_target(c, s, cands, c.int_const(fmt::format("tie_{}", r).c_str()),
                                                  c.int_const(fmt::format("fallback_{}", r).c_str()))
                   : occupancy::deterministic_target(c, cands);
    z3::expr ni = here.i, nj = here.j;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      ni = z3::ite(target == c.int_val(static_cast<int>(k)), cells[k].i, ni);
      nj = z3::ite(target == c.int_val(static_cast<int>(k)), cells[k].j, nj);
    }
    const Cell moved{c.int_const(fmt::format("i_{}_after", r).c_str()), c.int_const(fmt::format("j_{}_after", r).c_str())};
    s.add(moved.i == ni && moved.j == nj);
    pos[static_cast<std::size_t>(r)] = moved;
  }
  z3::expr ok = c.bool_val(true);
  for (int r = 0; r < robots; ++r) {
    const Cell& p = pos[static_cast<std::size_t>(r)];
    ok = ok && in_map(p, n) && !obstacle(p.i, p.j);
    for (int q = 0; q < r; ++q) ok = ok && !same(pos[static_cast<std::size_t>(q)], p);
  }
  s.add(!ok);
  return session.check(s, fmt::format("{}-r{}", stochastic ? "stochastic" : "deterministic", robots));
}

Outcome run(Session& session) {
  for (int robots = 1; robots <= kMaxRobots; ++robots)
    for (bool stochastic : {false, true}) {
      const z3::check_result r = check(session, robots, stochastic);
      if (r == z3::sat)
        return {Verdict::refuted, "sat: query " + session.queries().back().label + " has a counterexample", {}};
      if (r != z3::unsat) return {Verdict::unknown, "unknown on query " + session.queries().back().label, {}};
    }
  return {Verdict::proved,
          fmt::format("unsat: deterministic and stochastic, 1..{} robots, {} queries", kMaxRobots,
                      session.queries().size()),
          {}};
}

}  // namespace

std::vector<Obligation> occupancy_obligations() {
  return {Obligation{
      "occupancy",
      "One planning step of the deterministic or stochastic rule set, from a state with every "
      "robot in the map, off obstacles and alone in its cell, keeps all three.",
      Verdict::proved,
      {"symbolic window contents: the map size, the obstacle map and the keys pow(tau, phi) of "
       "every cell are free (uninterpreted functions), so any pheromone and any obstacles",
       "the choice is SPEC.md section 3 over the window in raster order; the stochastic rule's "
       "random draws are free choices among the minima and among the free candidates",
       "s_range = 1 (a 3 x 3 window) and 1..6 robots with symbolic positions"},
      run}};
}

}  // namespace swarmcheck::proofs
