#pragma once
// RapidCheck generators of exploration cases for the differential harness. Type-directed, so
// nearly every case is a valid scenario that reaches deep code, and built by families so that
// each class of state a fault could hide in is reached by construction, not by luck:
//   standard:      maps 1..64, robots from one to a good share of the free cells, obstacles,
//                  every rule set and mode, parameters with their edge values (phi <= 0,
//                  ertu * step_size >= 1, s_range beyond the map, epsilon 0, tiny and huge a1, a2)
//   long_horizon:  small maps with a walled-in pocket no robot can reach, so the run never
//                  completes: thousands of steps, some beyond 2^15, with cells read long after
//                  they were written (lazy decay at large ages, tick counters past powers of two)
//   edge_poses:    robots starting off the cell centres: on a cell's lower edge, a few ulps
//                  below the next edge, at -0.0, tiny offsets; cosim mostly, so that controllers
//                  and bodies run from them (and reach headings around +-pi)
//   crowds:        a few tight crowds on an empty map: sparse overall (the parallel path's band
//                  schedule) but chains of robots within reach of each other, in any index order,
//                  often across the strips' edges; always on the parallel path
//   corridors:     robots packed into horizontal corridors between walls (half the cases all
//                  closed, else with a few gaps), dense
//                  enough for the strip schedule: most steps keep every robot on its row (the
//                  schedule reuses its lists), some move one robot across a gap or within a
//                  corridor, some exchange rows (the lists must be built again); parallel path
// Every family draws whether the impl plans and deposits in parallel (over strips) even for few robots.
#include <rapidcheck.h>

#include <cstdint>
#include <string_view>

#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::conformance::exploration {

enum class Family { standard, long_horizon, edge_poses, crowds, corridors, real_body };
std::string_view family_name(Family f);

struct ExplorationCase {
  swarmcheck::exploration::Scenario scenario;
  Family family = Family::standard;
  bool grouped = false;   // impl option: the parallel path (strips, 4 threads) always
};

// max_steps: the steps a standard case runs at most (the scenario's max_steps is set from it;
// long-horizon cases run far longer by design).
rc::Gen<ExplorationCase> gen_exploration_case(int64_t max_steps);

ExplorationOptions impl_options(const ExplorationCase& c);

}  // namespace swarmcheck::conformance::exploration
