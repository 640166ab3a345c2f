// The thesis interface's Controller FMU (UController.fmu): the thesis controller's law
// (spec/exploration/controller_thesis.hpp) for one robot, with the published UController's
// variables, every port Real (the flag handshake as 0.0 / 1.0: onDestinationInput counts as given
// when it is not 0.0, as the thesis's C code tests it).
#include <cmath>
#include <string>

#include "fmi/fmu/kinds.hpp"
#include "fmi/fmu/thesis_ports.hpp"
#include "spec/exploration/controller_thesis.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

class ThesisControllerComponent final : public Component {
 public:
  ThesisControllerComponent() : Component("thesis controller") {
    table_.bind(params_, Role::parameter);
    table_.bind(in_, Role::input);
    table_.bind(out_, Role::output);
  }

  void defaults() override {
    const ex::ThesisControllerParams tp;
    const ex::ControllerState s = ex::initial_thesis_controller();
    params_ = {tp.k_beta, tp.k_v, s.maneuver, s.beta_rad, 0.0, 0.0, 0.0};
    in_ = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    out_ = {s.servo_left, s.servo_right, static_cast<double>(s.on_destination_output)};
  }

  void initialize() override {
    if (!std::isfinite(params_.k_beta) || !std::isfinite(params_.k_v) || !std::isfinite(params_.beta))
      throw FmuError("k_beta, k_v and beta must be finite");
    if (params_.maneuver != 1 && params_.maneuver != 2)
      throw FmuError("maneuver: expected 1 (orient) or 2 (drive), got " + std::to_string(params_.maneuver));
  }

  void step(double /*t_s*/, double h_s) override {
    if (out_.onDestinationOutput != 0.0 && out_.onDestinationOutput != 1.0)
      throw FmuError("onDestinationOutput is " + std::to_string(out_.onDestinationOutput) +
                     ", not 0.0 or 1.0: a restored state was altered");
    if (params_.maneuver != 1 && params_.maneuver != 2)
      throw FmuError("maneuver is " + std::to_string(params_.maneuver) + ", not 1 or 2: a restored state was altered");
    ex::ThesisControllerParams tp;
    tp.k_beta = params_.k_beta;
    tp.k_v = params_.k_v;
    const ex::ControllerState before{params_.maneuver, out_.onDestinationOutput == 1.0 ? 1 : 0, params_.beta,
                                     out_.servoLeft, out_.servoRight, 0.0};
    const ex::ControllerInputs inputs{{in_.x, in_.y, in_.phi},
                                      {in_.xDesired, in_.yDesired},
                                      in_.onDestinationInput != 0.0 ? 1 : 0,
                                      h_s};
    const ex::ControllerState next = ex::thesis_controller_step(tp, before, inputs);
    const ex::ControllerLocals l = ex::thesis_controller_locals(tp, before, inputs);
    out_ = {next.servo_left, next.servo_right, static_cast<double>(next.on_destination_output)};
    params_.maneuver = next.maneuver;
    params_.beta = next.beta_rad;
    params_.rho = l.rho_m;
    params_.v = l.v;
    params_.w = l.w;
  }

 private:
  ThesisControllerParameters params_{};
  ThesisControllerInputs in_{};
  ThesisControllerOutputs out_{};
};

}  // namespace

std::unique_ptr<Component> make_thesis_controller_component(const FmuSetup&) {
  return std::make_unique<ThesisControllerComponent>();
}

}  // namespace swarmcheck::fmi
