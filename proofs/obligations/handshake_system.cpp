#include "proofs/obligations/handshake_system.hpp"

#include <string>

#include "proofs/obligations/handshake_concrete.hpp"

namespace swarmcheck::proofs::handshake {

using S = num::Symbolic;

exploration::ControllerCoreT<S> traced_controller_rule(const exploration::ControllerParamsT<S>& p,
                                                       const exploration::ControllerCoreT<S>& s,
                                                       const exploration::ControllerInputsT<S>& in) {
  const exploration::ControllerCoreT<S> n = exploration::controller_rule<S>(p, s, in);
  constexpr const char* fn = "exploration::controller_rule";
  return {num::traced(fn, n.idle), num::traced(fn, n.driving), num::traced(fn, n.beta_rad),
          num::traced(fn, n.servo_left), num::traced(fn, n.servo_right), num::traced(fn, n.target_theta_rad)};
}

void SymbolicFlagSystem::robots_step(const sym::Bool& env_output) {
  accept.assign(internal.size(), sym::Bool(false));
  for (std::size_t i = 0; i < internal.size(); ++i) {
    const exploration::ControllerCoreT<S> before = internal[i];
    const RobotView<S>& r = robots[i];
    internal[i] = traced_controller_rule(params, before, {r.x, r.y, r.theta, r.x_desired, r.y_desired, env_output,
                                                          sym::Real(kHandshakeStep_s)});
    accept[i] = before.idle && !internal[i].idle;
    port[i] = late ? before.idle : internal[i].idle;
  }
}

void SymbolicEpochSystem::robots_step(const sym::Int& env_epoch) {
  accept.assign(internal.size(), sym::Bool(false));
  for (std::size_t i = 0; i < internal.size(); ++i) {
    const exploration::EpochControllerT<S> before = internal[i];
    const RobotView<S>& r = robots[i];
    const sym::Bool arrived = num::traced("exploration::arrived_rule",
                                          exploration::arrived_rule<S>({r.x_desired - r.x, r.y_desired - r.y}, tolerance));
    internal[i] = exploration::epoch_controller_rule<S>(before, env_epoch, arrived);
    accept[i] = internal[i].ack != before.ack;
    port[i] = late ? exploration::EpochPortT<S>{before.ack, before.done}
                   : exploration::EpochPortT<S>{internal[i].ack, internal[i].done};
  }
}

void SymbolicEpochSystem::environment_step(const std::vector<exploration::EpochPortT<S>>& read) {
  std::vector<sym::Int> acks;
  std::vector<sym::Bool> done;
  for (const auto& p : read) {
    acks.push_back(p.ack);
    done.push_back(p.done);
  }
  const exploration::EpochStepT<S> e = exploration::epoch_environment_rule<S>(epoch, acks, done);
  plan = e.plan;
  epoch = e.epoch;
}

namespace {

constexpr int kProbeRobots = 2;

RobotView<S> free_robot(int i) {
  auto r = [&](const char* what) { return sym::Real::var(std::string(what) + "_" + std::to_string(i)); };
  return {r("x"), r("y"), r("theta"), r("wx"), r("wy")};
}

SymbolicFlagSystem free_flag_system(bool late) {
  SymbolicFlagSystem sys;
  sys.params = exploration::symbolic_controller_params(exploration::RobotParams{});
  sys.env = {sym::Bool::var("flag"), sym::Bool::var("env_out")};
  sys.late = late;
  for (int i = 0; i < kProbeRobots; ++i) {
    const std::string k = std::to_string(i);
    sys.internal.push_back({sym::Bool::var("out_" + k), sym::Bool::var("driving_" + k), sym::Real::var("beta_" + k),
                            sym::Real::var("servo_left_" + k), sym::Real::var("servo_right_" + k),
                            sym::Real::var("target_" + k)});
    sys.port.push_back(late ? sym::Bool::var("port_out_" + k) : sys.internal.back().idle);
    sys.robots.push_back(free_robot(i));
  }
  return sys;
}

}  // namespace

std::vector<sym::NodePtr> step_quantities(const Variant& v) {
  const exploration::MasterOrder order =
      v.master == Master::jacobi ? exploration::MasterOrder::jacobi : exploration::MasterOrder::gauss_seidel;
  std::vector<sym::NodePtr> out;
  if (v.protocol == Protocol::flag) {
    SymbolicFlagSystem sys = free_flag_system(v.late_controller);
    exploration::master_step(exploration::Mode::cosim, sys, order);
    out.push_back(sys.plan.node());
    for (const sym::Bool& a : sys.accept) out.push_back(a.node());
    return out;
  }
  SymbolicEpochSystem sys;
  sys.tolerance = sym::Real::var("tolerance");
  sys.epoch = sym::Int::var("epoch");
  sys.late = v.late_controller;
  for (int i = 0; i < kProbeRobots; ++i) {
    const std::string k = std::to_string(i);
    sys.internal.push_back({sym::Int::var("ack_" + k), sym::Bool::var("done_" + k)});
    sys.port.push_back(v.late_controller ? exploration::EpochPortT<S>{sym::Int::var("port_ack_" + k), sym::Bool::var("port_done_" + k)}
                                         : exploration::EpochPortT<S>{sys.internal.back().ack, sys.internal.back().done});
    sys.robots.push_back(free_robot(i));
  }
  exploration::master_step(exploration::Mode::cosim, sys, order);
  out.push_back(sys.plan.node());
  for (const sym::Bool& a : sys.accept) out.push_back(a.node());
  return out;
}

std::vector<sym::NodePtr> servo_quantities() {
  SymbolicFlagSystem sys = free_flag_system(false);
  exploration::master_step(exploration::Mode::cosim, sys);
  std::vector<sym::NodePtr> out;
  for (const auto& c : sys.internal) {
    out.push_back(c.servo_left.node());
    out.push_back(c.servo_right.node());
  }
  return out;
}

}  // namespace swarmcheck::proofs::handshake
