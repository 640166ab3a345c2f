#include "proofs/obligations/handshake_concrete.hpp"

#include <cmath>
#include <memory>

#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

using C = num::Concrete;

// A controller step: the new internal output; sets accept.
ControllerPort controller(const Variant& v, const exploration::RobotParams& rp, ConcreteState& s,
                          std::size_t i, bool env_out, int32_t env_epoch, const RobotInput& in, StepEvents& ev) {
  ControllerPort p = s.internal[i];
  const exploration::BodyState pose{in.x_m, in.y_m, in.theta_rad};
  const exploration::Point_m wp{s.x_desired_m[i], s.y_desired_m[i]};
  if (v.protocol == Protocol::flag) {
    const exploration::ControllerState before = s.ctrl[i];
    s.ctrl[i] = exploration::controller_step(rp, before,
                                             exploration::ControllerInputs{pose, wp, env_out ? 1 : 0, kHandshakeStep_s});
    p.out = s.ctrl[i].on_destination_output == 1;
    ev.accept[i] = before.on_destination_output == 1 && !p.out;
    return p;
  }
  const bool arrived = exploration::arrived_rule<C>({wp[0] - pose.x_m, wp[1] - pose.y_m}, rp.tolerance_m);
  const exploration::EpochControllerT<C> n = exploration::epoch_controller_rule<C>({p.ack, p.done}, env_epoch, arrived);
  ev.accept[i] = n.ack != p.ack;
  p.ack = n.ack;
  p.done = n.done;
  return p;
}

// The Environment's step, reading the controllers' ports; returns whether it plans.
bool environment(const Variant& v, ConcreteState& s, const std::vector<ControllerPort>& ports) {
  const std::size_t n = ports.size();
  if (v.protocol == Protocol::flag) {
    const bool all = exploration::all_arrived_rule<C>(n, [&](std::size_t k) { return ports[k].out; });
    const exploration::HandshakeStep hs = exploration::environment_handshake(s.env, all);
    s.env = hs.next;
    return hs.plan;
  }
  std::vector<int32_t> acks(n);
  const std::unique_ptr<bool[]> done(new bool[n]);
  for (std::size_t k = 0; k < n; ++k) {
    acks[k] = ports[k].ack;
    done[k] = ports[k].done;
  }
  const exploration::EpochStepT<C> e =
      exploration::epoch_environment_rule<C>(s.epoch, acks, std::span<const bool>(done.get(), n));
  s.epoch = e.epoch;
  return e.plan;
}

}  // namespace

const char* to_string(Master m) { return m == Master::jacobi ? "jacobi" : "gauss-seidel"; }

bool at_waypoint(double x_m, double y_m, double x_desired_m, double y_desired_m, double tolerance_m) {
  return std::fabs(x_desired_m - x_m) + std::fabs(y_desired_m - y_m) < tolerance_m;
}

ConcreteState initial_state(const Variant&, int robots) {
  ConcreteState s;
  s.env = exploration::initial_handshake();
  const auto n = static_cast<std::size_t>(robots);
  s.ctrl.assign(n, exploration::initial_controller());
  s.internal.assign(n, ControllerPort{});
  s.port = s.internal;
  s.x_desired_m.assign(n, 0.5);
  s.y_desired_m.assign(n, 0.5);
  s.reached.assign(n, true);
  s.fresh.assign(n, false);
  return s;
}

StepEvents step(const Variant& v, const exploration::RobotParams& rp, ConcreteState& s,
                const std::vector<RobotInput>& in) {
  const std::size_t n = s.internal.size();
  StepEvents ev;
  ev.accept.assign(n, false);
  ev.at_waypoint.assign(n, false);
  // Every component reads the outputs of the previous step (Jacobi); under Gauss-Seidel the
  // controllers step first and the Environment reads their new outputs.
  const bool env_out = s.env.on_destination_output == 1;
  const int32_t env_epoch = s.epoch;
  std::vector<ControllerPort> next(n);
  for (std::size_t i = 0; i < n; ++i) {
    ev.at_waypoint[i] = at_waypoint(in[i].x_m, in[i].y_m, s.x_desired_m[i], s.y_desired_m[i], rp.tolerance_m);
    next[i] = controller(v, rp, s, i, env_out, env_epoch, in[i], ev);
  }
  std::vector<ControllerPort> next_port(n);
  for (std::size_t i = 0; i < n; ++i) next_port[i] = v.late_controller ? s.internal[i] : next[i];
  ev.plan = environment(v, s, v.master == Master::jacobi ? s.port : next_port);
  for (std::size_t i = 0; i < n; ++i) {
    const bool reached_now = s.reached[i] || ev.at_waypoint[i];
    if (ev.plan && !reached_now && ev.violated.empty()) ev.violated = "no-early-plan";
    if (ev.accept[i] && !s.fresh[i] && ev.violated.empty()) ev.violated = "fresh-acceptance";
    s.reached[i] = !ev.plan && reached_now;
    s.fresh[i] = ev.plan || (s.fresh[i] && !ev.accept[i]);
    if (ev.plan) {
      s.x_desired_m[i] = in[i].new_x_desired_m;
      s.y_desired_m[i] = in[i].new_y_desired_m;
    }
  }
  s.internal = next;
  s.port = next_port;
  return ev;
}

}  // namespace swarmcheck::proofs::handshake
