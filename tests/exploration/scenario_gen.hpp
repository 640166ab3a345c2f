#pragma once
// RapidCheck generator of valid scenarios for the model's property tests: small maps, random
// obstacles, robots on distinct free cells, every rule set and mode, parameters in their domain.
#include <rapidcheck.h>

#include <algorithm>
#include <numeric>

#include "spec/exploration/scenario.hpp"

namespace swarmcheck::exploration::testing {

inline rc::Gen<Scenario> gen_scenario(int32_t map_max = 12, int64_t abstract_steps = 60,
                                      int64_t cosim_steps = 600) {
  return rc::gen::exec([=] {
    Scenario s = default_scenario();
    s.map_size = *rc::gen::inRange<int32_t>(1, map_max + 1);
    const int32_t cells = s.map_size * s.map_size;
    std::vector<int32_t> order(static_cast<std::size_t>(cells));
    std::iota(order.begin(), order.end(), 0);
    // A seeded shuffle: RapidCheck draws the permutation, so shrinking stays deterministic.
    for (std::size_t k = order.size(); k > 1; --k)
      std::swap(order[k - 1], order[*rc::gen::inRange<std::size_t>(0, k)]);
    const int32_t robots = *rc::gen::inRange<int32_t>(1, std::max(2, cells / 2 + 1));
    const int32_t obstacles = *rc::gen::inRange<int32_t>(0, cells - robots + 1);
    s.robots.clear();
    s.obstacles.clear();
    s.cell_size = *rc::gen::element(1.0, 0.5, 2.0);
    for (int32_t k = 0; k < robots; ++k) {
      const int32_t c = order[static_cast<std::size_t>(k)];
      s.robots.push_back({(c / s.map_size + 0.5) * s.cell_size, (c % s.map_size + 0.5) * s.cell_size});
    }
    for (int32_t k = robots; k < robots + obstacles; ++k) {
      const int32_t c = order[static_cast<std::size_t>(k)];
      s.obstacles.push_back({c / s.map_size, c % s.map_size});
    }
    s.rule = *rc::gen::elementOf(all_rule_sets());
    s.mode = *rc::gen::element(Mode::abstract, Mode::cosim);
    s.seed = *rc::gen::arbitrary<uint64_t>();
    s.params.s_range = *rc::gen::inRange<int32_t>(1, 4);
    s.params.a1 = *rc::gen::element(0.5, 1e-3, 2.0, 1e3);
    s.params.a2 = *rc::gen::element(0.5, 1e-3, 3.0);
    s.params.epsilon = *rc::gen::element(0.5, 0.0, 1.0);
    s.params.max_ph = *rc::gen::element(2.0, 0.0, 10.0);
    s.params.ertu = *rc::gen::element(0.1, 0.0, 1.0, 20.0);
    s.params.phi = *rc::gen::element(1.0, 0.0, -1.0, 2.5);
    s.params.step_size = *rc::gen::element(0.1, 0.05);
    s.max_steps = s.mode == Mode::abstract ? abstract_steps : cosim_steps;
    validate(s);
    return s;
  });
}

}  // namespace swarmcheck::exploration::testing
