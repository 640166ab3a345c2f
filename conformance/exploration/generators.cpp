#include "conformance/exploration/generators.hpp"

#include <algorithm>
#include <numeric>

#include "spec/exploration/scenario.hpp"

namespace swarmcheck::conformance {

using namespace exploration;

namespace {

Params gen_params(int32_t map_size) {
  Params p = default_params();
  p.s_range = *rc::gen::weightedOneOf<int32_t>({{6, rc::gen::just(1)},
                                                {3, rc::gen::inRange(2, 4)},
                                                {1, rc::gen::just(map_size + 3)}});   // beyond the map
  p.a1 = *rc::gen::element(0.5, 1.0, 1e-9, 1e9);
  p.a2 = *rc::gen::element(0.5, 2.0, 1e-9, 1e9);
  p.epsilon = *rc::gen::element(0.5, 0.0, 1.0);
  p.max_ph = *rc::gen::element(2.0, 0.0, 5.0);
  p.eta = *rc::gen::element(0.9, 1.0, 2.0);
  p.phi = *rc::gen::element(1.0, 1.0, 0.0, -1.0, 2.0);
  p.lambda = *rc::gen::element(1.0, 0.0, -2.0);
  p.step_size = *rc::gen::element(0.1, 0.05, 0.2);
  // ertu * step_size: 0, small, exactly 1, and beyond 1 (the clamp matters).
  p.ertu = *rc::gen::element(0.1, 0.0, 1.0, 1.0 / p.step_size, 2.5 / p.step_size);
  return p;
}

}  // namespace

rc::Gen<ExplorationCase> gen_exploration_case(int64_t max_steps) {
  return rc::gen::exec([max_steps] {
    ExplorationCase c;
    Scenario& s = c.scenario;
    s = default_scenario();
    s.map_size = *rc::gen::inRange<int32_t>(1, 65);   // size-scaled: small maps come first
    const int32_t cells = s.map_size * s.map_size;
    // A random permutation of the cells, drawn from RapidCheck so that it shrinks.
    std::vector<int32_t> order(static_cast<std::size_t>(cells));
    std::iota(order.begin(), order.end(), 0);
    const int32_t placed_max = std::min(cells, 400);
    for (int32_t k = 0; k < placed_max; ++k)
      std::swap(order[static_cast<std::size_t>(k)], order[*rc::gen::inRange<std::size_t>(static_cast<std::size_t>(k), order.size())]);
    const int32_t robots = *rc::gen::inRange<int32_t>(1, std::max(2, std::min(placed_max, cells * 2 / 3) + 1));
    const int32_t obstacles = *rc::gen::inRange<int32_t>(0, std::max(1, std::min(placed_max - robots, cells / 3) + 1));
    s.cell_size = *rc::gen::element(1.0, 0.5, 3.0);
    s.robots.clear();
    s.obstacles.clear();
    for (int32_t k = 0; k < robots; ++k) {
      const int32_t cell = order[static_cast<std::size_t>(k)];
      s.robots.push_back({(cell / s.map_size + 0.5) * s.cell_size, (cell % s.map_size + 0.5) * s.cell_size});
    }
    for (int32_t k = robots; k < robots + obstacles; ++k) {
      const int32_t cell = order[static_cast<std::size_t>(k)];
      s.obstacles.push_back({cell / s.map_size, cell % s.map_size});
    }
    s.rule = *rc::gen::element(RuleSet::thesis, RuleSet::deterministic, RuleSet::stochastic);
    s.mode = *rc::gen::weightedOneOf<Mode>({{3, rc::gen::just(Mode::abstract)}, {1, rc::gen::just(Mode::cosim)}});
    s.seed = *rc::gen::arbitrary<uint64_t>();
    s.params = gen_params(s.map_size);
    s.max_steps = s.mode == Mode::cosim ? 3 * max_steps : max_steps;   // cosim plans every ~100 steps
    c.grouped = *rc::gen::arbitrary<bool>();
    validate(s);
    return c;
  });
}

ExplorationOptions impl_options(const ExplorationCase& c) {
  ExplorationOptions o;
  if (c.grouped) {
    o.parallel_min_robots = 1;
    o.parallel_min_bodies = 1;
  }
  return o;
}

}  // namespace swarmcheck::conformance
