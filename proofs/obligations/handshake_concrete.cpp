#include "proofs/obligations/handshake_concrete.hpp"

#include <cmath>
#include <memory>

#include "spec/exploration/controller.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/master.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

using C = num::Concrete;

// The systems master_step runs for the replay: the concrete counterparts of handshake_system.hpp,
// each controller through controller_step (flag) or arrived_rule and epoch_controller_rule
// (epoch), the Environment through handshake_stage (flag) or epoch_environment_rule (epoch).
struct FlagSystem {
  const exploration::RobotParams& rp;
  ConcreteState& s;
  const std::vector<RobotInput>& in;
  StepEvents& ev;
  bool late;
  std::vector<exploration::ControllerState> ports;   // what the Environment reads: onDestinationOutput

  std::span<const exploration::ControllerState> controllers() const { return ports; }
  int32_t environment_output() const { return s.env.on_destination_output; }
  void robots_step(int32_t env_output) {
    for (std::size_t i = 0; i < s.ctrl.size(); ++i) {
      const exploration::ControllerState before = s.ctrl[i];
      s.ctrl[i] = exploration::controller_step(
          rp, before,
          exploration::ControllerInputs{{in[i].x_m, in[i].y_m, in[i].theta_rad}, {s.x_desired_m[i], s.y_desired_m[i]},
                                        env_output, kHandshakeStep_s});
      ev.accept[i] = before.on_destination_output == 1 && s.ctrl[i].on_destination_output == 0;
      s.internal[i].out = s.ctrl[i].on_destination_output == 1;
      s.port[i].out = (late ? before.on_destination_output : s.ctrl[i].on_destination_output) == 1;
      ports[i].on_destination_output = s.port[i].out ? 1 : 0;
    }
  }
  void environment_step(bool arrived) { ev.plan = exploration::handshake_stage(exploration::Mode::cosim, s.env, arrived); }
  void place_bodies_on_waypoints() {}
};

struct EpochSystem {
  const exploration::RobotParams& rp;
  ConcreteState& s;
  const std::vector<RobotInput>& in;
  StepEvents& ev;
  bool late;
  std::vector<exploration::EpochPortT<C>> ports;

  std::span<const exploration::EpochPortT<C>> controllers() const { return ports; }
  int32_t environment_output() const { return s.epoch; }
  void robots_step(int32_t env_epoch) {
    for (std::size_t i = 0; i < s.internal.size(); ++i) {
      const ControllerPort before = s.internal[i];
      const bool arrived = exploration::arrived_rule<C>(
          {s.x_desired_m[i] - in[i].x_m, s.y_desired_m[i] - in[i].y_m}, rp.tolerance_m);
      const exploration::EpochControllerT<C> n =
          exploration::epoch_controller_rule<C>({before.ack, before.done}, env_epoch, arrived);
      ev.accept[i] = n.ack != before.ack;
      s.internal[i].ack = n.ack;
      s.internal[i].done = n.done;
      s.port[i] = late ? before : s.internal[i];
      ports[i] = {s.port[i].ack, s.port[i].done};
    }
  }
  void environment_step(const std::vector<exploration::EpochPortT<C>>& read) {
    std::vector<int32_t> acks;
    const std::unique_ptr<bool[]> done(new bool[read.size()]);
    for (std::size_t k = 0; k < read.size(); ++k) {
      acks.push_back(read[k].ack);
      done[k] = read[k].done;
    }
    const exploration::EpochStepT<C> e =
        exploration::epoch_environment_rule<C>(s.epoch, acks, std::span<const bool>(done.get(), read.size()));
    s.epoch = e.epoch;
    ev.plan = e.plan;
  }
  void place_bodies_on_waypoints() {}
};

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
  for (std::size_t i = 0; i < n; ++i)
    ev.at_waypoint[i] = at_waypoint(in[i].x_m, in[i].y_m, s.x_desired_m[i], s.y_desired_m[i], rp.tolerance_m);
  // The master that runs: spec's master_step, in the variant's order.
  const exploration::MasterOrder order =
      v.master == Master::jacobi ? exploration::MasterOrder::jacobi : exploration::MasterOrder::gauss_seidel;
  if (v.protocol == Protocol::flag) {
    FlagSystem sys{rp, s, in, ev, v.late_controller, {}};
    for (const ControllerPort& p : s.port) {
      exploration::ControllerState c = exploration::initial_controller();
      c.on_destination_output = p.out ? 1 : 0;
      sys.ports.push_back(c);
    }
    exploration::master_step(exploration::Mode::cosim, sys, order);
  } else {
    EpochSystem sys{rp, s, in, ev, v.late_controller, {}};
    for (const ControllerPort& p : s.port) sys.ports.push_back({p.ack, p.done});
    exploration::master_step(exploration::Mode::cosim, sys, order);
  }
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
  return ev;
}

}  // namespace swarmcheck::proofs::handshake
