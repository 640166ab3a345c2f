// The symbolic world the proofs interpret the Environment's stages in (proofs/obligations/
// symbolic_world.hpp) against the executed code: the symbolic window visits the concrete window's
// cells in order, and spec's IndexOrder::plan interpreted on a symbolic map, with every value the
// step reads fixed, moves the robots exactly as the executed IndexOrder::plan on a concrete grid.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <vector>

#include "proofs/obligations/replay_grid.hpp"
#include "proofs/obligations/symbolic_world.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::proofs {
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededProofsWorldTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using S = num::Symbolic;
using exploration::CellIndex;

RC_GTEST_PROP(SymbolicWorld, SymbolicWindowVisitsTheConcreteWindowsCellsInOrder, ()) {
  const int32_t n = *rc::gen::inRange(1, 12);
  const int32_t s_range = *rc::gen::inRange(1, 5);
  const CellIndex c{*rc::gen::inRange(0, n), *rc::gen::inRange(0, n)};
  std::vector<std::array<int32_t, 4>> concrete, symbolic;
  exploration::for_each_window_cell(exploration::window_around(c, s_range, n), c, s_range,
                                    [&](CellIndex x, bool in, int32_t di, int32_t dj) {
                                      if (in) concrete.push_back({x[0], x[1], di, dj});
                                    });
  // With literal inputs every symbolic operation folds to the concrete one.
  const exploration::CellOf<S> sc{sym::Int(c[0]), sym::Int(c[1])};
  exploration::for_each_window_cell(
      exploration::window_around(sc, s_range, sym::Int(n)), sc, s_range,
      [&](const exploration::CellOf<S>& x, const sym::Bool& in, int32_t di, int32_t dj) {
        RC_ASSERT(in.is_literal());
        if (in.literal())
          symbolic.push_back({static_cast<int32_t>(x[0].literal()), static_cast<int32_t>(x[1].literal()), di, dj});
      });
  RC_ASSERT(concrete == symbolic);
}

RC_GTEST_PROP(SymbolicWorld, SymbolicPlanningStepInZ3MovesTheRobotsAsTheExecutedStep, ()) {
  const auto rule = *rc::gen::element(exploration::RuleSet::deterministic, exploration::RuleSet::thesis);
  const int32_t n = *rc::gen::inRange(2, 6);
  const int robots = *rc::gen::inRange(1, 3);
  std::vector<CellIndex> cells;
  while (static_cast<int>(cells.size()) < robots) {
    const CellIndex c{*rc::gen::inRange(0, n), *rc::gen::inRange(0, n)};
    if (std::find(cells.begin(), cells.end(), c) == cells.end()) cells.push_back(c);
  }
  // The concrete world.
  exploration::Scenario sc = exploration::default_scenario();
  sc.map_size = n;
  sc.rule = rule;
  sc.params.s_range = 1;
  sc.params.eta = 1.0;   // eta_term 1 and the thesis rule's start 1000: exact in both theories
  sc.obstacles.clear();
  const exploration::EnvironmentConfig cfg = exploration::make_environment_config(sc);
  exploration::EnvironmentState env;
  env.tick = 1;
  ReplayGrid grid(cfg, 1);
  // The symbolic world, every value the step reads pinned to the concrete one.
  const world::Config scfg = world::symbolic_config(rule, 1);
  world::Environment senv = world::symbolic_environment(scfg, robots, "robot", 1);
  world::Grid sgrid(scfg, "map", 1, 1);
  z3::context c;
  Translator t(c, RealTheory::real);
  z3::solver s(c);
  const exploration::ChoiceTerms terms = exploration::choice_terms(sc.params);
  RC_ASSERT(terms.eta_term == 1.0 && terms.thesis_best_start == 1000.0);
  s.add(t(scfg.scenario.map_size) == n && t(scfg.terms.exact.eta_term) == 1 && t(scfg.terms.exact.thesis_best_start) == 1000);
  for (int k = 0; k < robots; ++k) {
    const CellIndex p = cells[static_cast<std::size_t>(k)];
    env.robots.push_back({p, exploration::centre_of(p, sc.cell_size)});
    env.deposit_centre.push_back(p);
    s.add(t(senv.robots[static_cast<std::size_t>(k)].cell[0]) == p[0] &&
          t(senv.robots[static_cast<std::size_t>(k)].cell[1]) == p[1]);
  }
  std::vector<CellIndex> pinned;   // neighbourhoods overlap: each cell is drawn and pinned once
  for (int k = 0; k < robots; ++k)
    for (int32_t di = -1; di <= 1; ++di)
      for (int32_t dj = -1; dj <= 1; ++dj) {
        const CellIndex x{cells[static_cast<std::size_t>(k)][0] + di, cells[static_cast<std::size_t>(k)][1] + dj};
        if (std::find(pinned.begin(), pinned.end(), x) != pinned.end()) continue;
        pinned.push_back(x);
        ReplayGrid::Content& content = grid.at(x);
        const auto robot = std::find(cells.begin(), cells.end(), x);
        if (robot != cells.end()) {
          content.occupant = static_cast<int32_t>(robot - cells.begin());
        } else if (exploration::in_map(x, n)) {
          content.obstacle = *rc::gen::arbitrary<bool>();
        }
        content.value = *rc::gen::inRange(1, 4);
        content.written = 1;
        const world::Cell sx{sym::Int(x[0]), sym::Int(x[1])};
        s.add(t(sgrid.obstacle(sx)) == c.bool_val(content.obstacle) && t(sgrid.occupant(sx)) == content.occupant &&
              t(sgrid.visited(sx)) == c.bool_val(content.visited) &&
              t(sgrid.stored(sx)) == c.real_val(static_cast<int>(content.value)));
      }
  exploration::IndexOrder{}.plan(cfg, env, grid);
  exploration::IndexOrder{}.plan(scfg, senv, sgrid);
  std::vector<z3::expr> cells_after;
  for (int k = 0; k < robots; ++k)
    for (int axis = 0; axis < 2; ++axis)
      cells_after.push_back(t(senv.robots[static_cast<std::size_t>(k)].cell[static_cast<std::size_t>(axis)]));
  s.add(t.side_conditions());   // after every translation: the quotients' and draws' facts
  RC_ASSERT(s.check() == z3::sat);
  const z3::model m = s.get_model();
  for (int k = 0; k < robots; ++k)
    for (int axis = 0; axis < 2; ++axis) {
      const z3::expr got = cells_after[static_cast<std::size_t>(2 * k + axis)];
      RC_ASSERT(m.eval(got, true).get_numeral_int64() == env.robots[static_cast<std::size_t>(k)].cell[static_cast<std::size_t>(axis)]);
      // And nothing else: the pinned values fix it.
      z3::solver other(c);
      other.add(s.assertions());
      other.add(got != c.int_val(env.robots[static_cast<std::size_t>(k)].cell[static_cast<std::size_t>(axis)]));
      RC_ASSERT(other.check() == z3::unsat);
    }
}

}  // namespace
}  // namespace swarmcheck::proofs
