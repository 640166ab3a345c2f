#pragma once
// The systems spec's master_step runs in the handshake proofs: the same stages as model/'s and
// impl/'s Systems (controllers(), environment_output(), robots_step, environment_step), with
// each robot's controller and the Environment's handshake the spec's rules, over symbolic values
// (SymbolicFlagSystem, SymbolicEpochSystem) or concrete ones (for the replay, handshake_concrete).
// Robot motion is not the systems' business: each robot's pose and waypoint in the step are given.
//
//   flag:   controller_rule (the whole controller), the Environment's handshake_stage_rule
//           (environment_handshake_rule) over environment_input = all_arrived_rule
//   epoch:  epoch_controller_rule with arrived_rule, the Environment's epoch_environment_rule
//           over environment_input = the ports as read
// A late controller's port shows the output it had before the step (one step old).
#include <span>
#include <vector>

#include "proofs/obligations/handshake_concrete.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/master.hpp"

namespace swarmcheck::proofs::handshake {

// One robot in one step, as a controller reads it: its pose and its current waypoint.
template <class D>
struct RobotView {
  typename D::Real x, y, theta, x_desired, y_desired;
};

struct SymbolicFlagSystem {
  using S = num::Symbolic;
  exploration::ControllerParamsT<S> params;
  exploration::HandshakeStateT<S> env;
  std::vector<exploration::ControllerCoreT<S>> internal;   // each controller's state
  std::vector<sym::Bool> port;                             // its onDestinationOutput as the Environment reads it
  std::vector<RobotView<S>> robots;                        // this step's poses and waypoints
  bool late = false;
  sym::Bool plan = false;
  std::vector<sym::Bool> accept;                           // controller i accepts a waypoint in the step

  std::span<const sym::Bool> controllers() const { return port; }
  sym::Bool environment_output() const { return env.output; }
  void robots_step(const sym::Bool& env_output);
  void environment_step(const sym::Bool& arrived) {
    plan = exploration::handshake_stage_rule<S>(exploration::Mode::cosim, env, arrived);
  }
  void place_bodies_on_waypoints() {}
};

// controller_rule's result, each field named as controller_rule's (the rule's own body is the
// lead's controller.cpp: the name is given where it is called).
exploration::ControllerCoreT<num::Symbolic> traced_controller_rule(const exploration::ControllerParamsT<num::Symbolic>& p,
                                                                  const exploration::ControllerCoreT<num::Symbolic>& s,
                                                                  const exploration::ControllerInputsT<num::Symbolic>& in);

struct SymbolicEpochSystem {
  using S = num::Symbolic;
  sym::Real tolerance;
  sym::Int epoch;
  std::vector<exploration::EpochControllerT<S>> internal;
  std::vector<exploration::EpochPortT<S>> port;
  std::vector<RobotView<S>> robots;
  bool late = false;
  sym::Bool plan = false;
  std::vector<sym::Bool> accept;

  std::span<const exploration::EpochPortT<S>> controllers() const { return port; }
  sym::Int environment_output() const { return epoch; }
  void robots_step(const sym::Int& env_epoch);
  void environment_step(const std::vector<exploration::EpochPortT<S>>& read);
  void place_bodies_on_waypoints() {}
};

// The handshake properties' quantities in one master step of two robots from any state (the
// step's symbolic interpretation from master_step down): whether the Environment plans, and
// whether each controller accepts.
std::vector<sym::NodePtr> step_quantities(const Variant& v);

// The servo commands of two robots' controllers after one master step (Jacobi, flag) from any
// state: what the servo range is about.
std::vector<sym::NodePtr> servo_quantities();

}  // namespace swarmcheck::proofs::handshake
