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
// The Gauss-Seidel order (MasterOrder::gauss_seidel; the FMI master's `gauss-seidel` over a
// multi-model whose instances are the controllers and bodies, then the Environment) steps the
// robots first and lets the Environment read the controllers' NEW outputs (x+):
//   robots:       as above, with env_output := env-.output
//   environment:  env+ := environment_step(env-, environment_input(ctrl+))
// What the Environment reads of the controllers is environment_input(controllers): all_arrived
// of their outputs (the flag handshake), or each one's port (the epoch handshake). master_step
// is a template over the System and over what its controllers() are, so that proofs/ runs this
// very function on symbolic controllers.
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
#include <vector>

#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/types.hpp"
#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {

// The Environment's input: every controller idle at its waypoint (all_arrived_rule of
// handshake.hpp over their onDestinationOutput).
bool all_arrived(std::span<const ControllerState> controllers);

// What the Environment reads of the controllers (see above): all_arrived for concrete ones;
// for symbolic ones, all_arrived_rule of their outputs, or a copy of their epoch ports.
inline bool environment_input(std::span<const ControllerState> controllers) { return all_arrived(controllers); }
sym::Bool environment_input(std::span<const sym::Bool> idle_outputs);
template <class D>
std::vector<EpochPortT<D>> environment_input(std::span<const EpochPortT<D>> ports) {
  std::vector<EpochPortT<D>> read;
  for (const EpochPortT<D>& p : ports)
    read.push_back({num::traced("exploration::master_step", p.ack), num::traced("exploration::master_step", p.done)});
  return read;
}

enum class MasterOrder { jacobi, gauss_seidel };

template <class System>
void master_step(Mode mode, System& system, MasterOrder order = MasterOrder::jacobi) {
  if (mode == Mode::abstract) {
    // A system with no such stages (the proofs' symbolic ones) has no abstract mode.
    if constexpr (requires { system.environment_step(true); }) {
      system.environment_step(true);
      system.place_bodies_on_waypoints();
    } else {
      SWARM_DEMAND(mode != Mode::abstract);
    }
    return;
  }
  if (order == MasterOrder::jacobi) {
    const auto arrived = environment_input(system.controllers());
    const auto env_output = system.environment_output();
    system.robots_step(env_output);
    system.environment_step(arrived);
  } else {
    const auto env_output = system.environment_output();
    system.robots_step(env_output);
    system.environment_step(environment_input(system.controllers()));
  }
}

// The observable state after a step: one trace record (what impl and model must agree on).
// `intocps` holds every robot's intocps body in index order, or nothing (kinematic bodies).
StepRecord make_step_record(const EnvironmentState& env, uint64_t pheromone_digest,
                            std::span<const ControllerState> controllers, std::span<const BodyState> bodies,
                            std::span<const IntocpsBodyState> intocps = {});

}  // namespace swarmcheck::exploration
