#include "proofs/obligations/handshake_concrete.hpp"

#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

using exploration::ControllerState;

const exploration::Point_m kWaypoint{0.5, 0.5};

// The spec's controller, with the robot on its waypoint or 3 m from it.
ControllerState spec_controller(const ControllerState& c, bool env_out, bool at_waypoint) {
  const exploration::BodyState pose{at_waypoint ? 0.5 : 3.5, 0.5, 0.0};
  return exploration::controller_step(exploration::RobotParams{}, c,
                                      exploration::ControllerInputs{pose, kWaypoint, env_out ? 1 : 0});
}

// A controller step: the new internal output; sets accept / arrive.
ControllerPort controller(const Variant& v, ConcreteState& s, std::size_t i, bool env_out,
                          int32_t env_epoch, bool arrival, StepEvents& ev) {
  ControllerPort p = s.internal[i];
  if (v.protocol == Protocol::flag) {
    const ControllerState before = s.ctrl[i];
    s.ctrl[i] = spec_controller(before, env_out, arrival);
    p.out = s.ctrl[i].on_destination_output == 1;
    ev.accept[i] = before.on_destination_output == 1 && !p.out;
    ev.arrive[i] = before.on_destination_output == 0 && p.out;
  } else if (env_epoch != p.ack) {   // a new epoch: accept its waypoint
    p.ack = env_epoch;
    p.done = false;
    ev.accept[i] = true;
  } else if (!p.done && arrival) {
    p.done = true;
    ev.arrive[i] = true;
  }
  return p;
}

// The Environment's step, reading the controllers' ports; returns whether it plans.
bool environment(const Variant& v, ConcreteState& s, const std::vector<ControllerPort>& ports) {
  if (v.protocol == Protocol::flag) {
    bool all = true;
    for (const ControllerPort& p : ports) all = all && p.out;
    const exploration::HandshakeStep hs = exploration::environment_handshake(s.env, all);
    s.env = hs.next;
    return hs.plan;
  }
  bool all = true;
  for (const ControllerPort& p : ports) all = all && p.ack == s.epoch && p.done;
  if (all) s.epoch = (s.epoch + 1) % kEpochs;
  return all;
}

}  // namespace

const char* to_string(Master m) { return m == Master::jacobi ? "jacobi" : "gauss-seidel"; }

ConcreteState initial_state(const Variant&, int robots) {
  ConcreteState s;
  s.env = exploration::initial_handshake();
  const auto n = static_cast<std::size_t>(robots);
  s.ctrl.assign(n, exploration::initial_controller());
  s.internal.assign(n, ControllerPort{});
  s.port = s.internal;
  s.reached.assign(n, true);
  s.fresh.assign(n, false);
  return s;
}

StepEvents step(const Variant& v, ConcreteState& s, const std::vector<bool>& arrival) {
  const std::size_t n = s.internal.size();
  StepEvents ev;
  ev.accept.assign(n, false);
  ev.arrive.assign(n, false);
  // Every component reads the outputs of the previous step (Jacobi); under Gauss-Seidel the
  // controllers step first and the Environment reads their new outputs.
  const bool env_out = s.env.on_destination_output == 1;
  const int32_t env_epoch = s.epoch;
  std::vector<ControllerPort> next(n);
  for (std::size_t i = 0; i < n; ++i)
    next[i] = controller(v, s, i, env_out, env_epoch, arrival[i], ev);
  std::vector<ControllerPort> next_port(n);
  for (std::size_t i = 0; i < n; ++i) next_port[i] = v.late_controller ? s.internal[i] : next[i];
  ev.plan = environment(v, s, v.master == Master::jacobi ? s.port : next_port);
  for (std::size_t i = 0; i < n; ++i) {
    const bool reached_now = s.reached[i] || ev.arrive[i];
    if (ev.plan && !reached_now && ev.violated.empty()) ev.violated = "no-early-plan";
    if (ev.accept[i] && !s.fresh[i] && ev.violated.empty()) ev.violated = "fresh-acceptance";
    s.reached[i] = !ev.plan && reached_now;
    s.fresh[i] = ev.plan || (s.fresh[i] && !ev.accept[i]);
  }
  s.internal = next;
  s.port = next_port;
  return ev;
}

}  // namespace swarmcheck::proofs::handshake
