#include "spec/exploration/master.hpp"

#include "spec/exploration/handshake.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

bool all_arrived(std::span<const ControllerState> controllers) {
  return all_arrived_rule<num::Concrete>(controllers.size(),
                                         [&](std::size_t k) { return controllers[k].on_destination_output == 1; });
}

sym::Bool environment_input(std::span<const sym::Bool> idle_outputs) {
  return num::traced("exploration::master_step",
                     all_arrived_rule<num::Symbolic>(idle_outputs.size(), [&](std::size_t k) { return idle_outputs[k]; }));
}

StepRecord make_step_record(const EnvironmentState& env, uint64_t pheromone_digest,
                            std::span<const ControllerState> controllers, std::span<const BodyState> bodies,
                            std::span<const IntocpsBodyState> intocps) {
  SWARM_DEMAND(controllers.size() == env.robots.size());
  SWARM_DEMAND(bodies.size() == env.robots.size());
  SWARM_DEMAND(intocps.empty() || intocps.size() == env.robots.size());
  StepRecord r;
  r.step = env.tick;
  r.planning_steps = env.planning_steps;
  r.handshake = env.handshake;
  r.visited = env.progress.visited;
  r.free_cells = env.progress.free_cells;
  r.eP = env.progress.eP;
  r.sTime = env.progress.sTime;
  r.pheromone_digest = pheromone_digest;
  r.robots.reserve(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    r.robots.push_back(RobotRecord{env.robots[k].cell, env.robots[k].waypoint, bodies[k], controllers[k], std::nullopt});
    if (!intocps.empty()) r.robots.back().body_states = intocps[k];
  }
  return r;
}

}  // namespace swarmcheck::exploration
