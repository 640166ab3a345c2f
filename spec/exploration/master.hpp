#pragma once
// The co-simulation master (spec/SPEC.md section 7): Jacobi fixed-step, as INTO-CPS Maestro.
// Every component reads the outputs of the previous step (x-), then all step by dt. No
// component has direct feedthrough, so the order of the stages below cannot change a result;
// it is fixed so that nothing needs copying (robots read the waypoints before the Environment
// replaces them).
//
//   exchange:     all_arrived := AND_i ctrl_i-.onDestinationOutput;  env_output := env-.output
//   robots:       ctrl_i+ := controller_step(ctrl_i-, {body_i-, env-.waypoint_i, env_output})
//                 body_i+ := body_step(body_i-, ctrl_i-.servo_left, ctrl_i-.servo_right, dt)
//   environment:  env+ := environment_step(env-, all_arrived)
// abstract mode (the thesis's preliminary version) has no controllers or bodies to speak of:
// every step plans and each robot then stands on its new waypoint.
//
// A System provides the stages:
//   std::span<const ControllerState> controllers() const
//   int32_t environment_output() const                  env-'s onDestinationOutput
//   void robots_step(int32_t env_output)                 every robot from x-, as above
//   void environment_step(bool all_arrived)
//   void place_bodies_on_waypoints()                     abstract mode
#include <cstdint>
#include <span>

#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

// The Environment's input: every controller idle at its waypoint (all_arrived_rule of
// handshake.hpp over their onDestinationOutput).
bool all_arrived(std::span<const ControllerState> controllers);

template <class System>
void master_step(Mode mode, System& system) {
  if (mode == Mode::abstract) {
    system.environment_step(true);
    system.place_bodies_on_waypoints();
    return;
  }
  const bool arrived = all_arrived(system.controllers());
  const int32_t env_output = system.environment_output();
  system.robots_step(env_output);
  system.environment_step(arrived);
}

// The observable state after a step: one trace record (what impl and model must agree on).
// `intocps` holds every robot's intocps body in index order, or nothing (kinematic bodies).
StepRecord make_step_record(const EnvironmentState& env, uint64_t pheromone_digest,
                            std::span<const ControllerState> controllers, std::span<const BodyState> bodies,
                            std::span<const IntocpsBodyState> intocps = {});

}  // namespace swarmcheck::exploration
