// The Controller FMU: spec controller_step for one robot. Its variables are its state: maneuver,
// onDestinationOutput, beta and the servos are exactly ControllerState, so a saved state is the
// variable list alone.
//   handshake 0 (the thesis's flag): onDestinationInput is the Environment's onDestinationOutput.
//   handshake 1 (epoch): the controller accepts when the Environment's epoch differs from the one
//   it last accepted (spec epoch_controller_rule); onDestinationOutput is still its idle flag,
//   which the Environment reads as `done` (both are raised by arrived_rule at the same step and
//   lowered by the acceptance).
// The scenario's controller decides the law: swarmcheck's (controller.hpp) or the thesis's
// published UController (controller_thesis.hpp; flag handshake only).
#include <cmath>
#include <optional>

#include "fmi/fmu/kinds.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/controller_thesis.hpp"
#include "spec/exploration/handshake.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

class ControllerComponent final : public Component {
 public:
  explicit ControllerComponent(ex::ControllerKind law) : Component("controller"), law_(law) {
    table_.bind(params_, Role::parameter);
    table_.bind(in_, Role::input);
    table_.bind(out_, Role::output);
    table_.bind(local_, Role::local);
  }

  void defaults() override {
    last_.reset();
    const ex::RobotParams rp;
    const ex::ThesisControllerParams tp;
    params_ = law_ == ex::ControllerKind::thesis ? ControllerParameters{tp.k_beta, tp.k_v, 0}
                                                 : ControllerParameters{rp.k_beta, rp.k_v, 0};
    in_ = {0.0, 0.0, 0.0, 0.0, 0.0, 0, 0};
    const ex::ControllerState s =
        law_ == ex::ControllerKind::thesis ? ex::initial_thesis_controller() : ex::initial_controller();
    out_ = {s.servo_left, s.servo_right, s.on_destination_output, 0, 0};
    local_ = {s.beta_rad, 0.0, 0.0, 0.0, s.maneuver, s.target_theta_rad};
  }

  void initialize() override {
    if (params_.handshake != 0 && params_.handshake != 1)
      throw FmuError("handshake: expected 0 (flag) or 1 (epoch), got " + std::to_string(params_.handshake));
    if (law_ == ex::ControllerKind::thesis && params_.handshake != 0)
      throw FmuError("handshake: the thesis controller has the flag handshake only (0), got 1");
    if (!std::isfinite(params_.k_beta) || !std::isfinite(params_.k_v))
      throw FmuError("k_beta and k_v must be finite");
  }

  void step(double /*t_s*/, double h_s) override {
    if ((local_.maneuver != 1 && local_.maneuver != 2) || (out_.onDestinationOutput != 0 && out_.onDestinationOutput != 1))
      throw FmuError("the controller's state is not one it can reach (maneuver " + std::to_string(local_.maneuver) +
                     ", onDestinationOutput " + std::to_string(out_.onDestinationOutput) + "): a restored state was altered");
    ex::RobotParams rp;
    rp.k_beta = params_.k_beta;
    rp.k_v = params_.k_v;
    const ex::ControllerState before{local_.maneuver, out_.onDestinationOutput, local_.beta, out_.servoLeft,
                                     out_.servoRight, local_.target};
    const ex::BodyState pose{in_.x, in_.y, in_.phi};
    const ex::Point_m waypoint{in_.xDesired, in_.yDesired};
    int32_t told = in_.onDestinationInput;
    bool accepted = false;
    if (params_.handshake == 1) {
      using C = num::Concrete;
      const bool at_waypoint =
          ex::arrived_rule<C>({waypoint[0] - pose.x_m, waypoint[1] - pose.y_m}, rp.tolerance_m);
      const ex::EpochControllerT<C> e = ex::epoch_controller_rule<C>(
          {out_.epochAck, out_.onDestinationOutput == 1}, in_.epochInput, at_waypoint);
      accepted = e.ack != out_.epochAck;
      told = accepted ? 1 : 0;
      out_.epochAck = e.ack;
    }
    const ex::ControllerInputs inputs{pose, waypoint, told, h_s};
    ex::ThesisControllerParams tp;
    tp.k_beta = params_.k_beta;
    tp.k_v = params_.k_v;
    const ex::ControllerState next = law_ == ex::ControllerKind::thesis ? ex::thesis_controller_step(tp, before, inputs)
                                                                        : ex::controller_step(rp, before, inputs);
    if (params_.handshake == 0) accepted = before.on_destination_output == 1 && next.on_destination_output == 0;
    out_.servoLeft = next.servo_left;
    out_.servoRight = next.servo_right;
    out_.onDestinationOutput = next.on_destination_output;
    out_.accepted += accepted ? 1 : 0;
    local_.beta = next.beta_rad;
    local_.maneuver = next.maneuver;
    local_.target = next.target_theta_rad;
    // rho, v and w cost the step's trigonometry again: computed when read (settle), not each step.
    last_ = Last{rp, tp, before, inputs};
  }

  void settle() override {
    if (!last_) return;
    const ex::ControllerLocals l = law_ == ex::ControllerKind::thesis
                                       ? ex::thesis_controller_locals(last_->tp, last_->before, last_->inputs)
                                       : ex::controller_locals(last_->rp, last_->before, last_->inputs);
    local_.rho = l.rho_m;
    local_.v = l.v;
    local_.w = l.w;
    last_.reset();
  }

 protected:
  // The locals are part of the saved state (settled before a save): nothing else to keep.
  void restore_extra(std::span<const uint8_t>& /*in*/) override { last_.reset(); }

 private:
  ex::ControllerKind law_;
  ControllerParameters params_{};
  ControllerInputs in_{};
  ControllerOutputs out_{};
  ControllerLocalVariables local_{};
  struct Last {
    ex::RobotParams rp;
    ex::ThesisControllerParams tp;
    ex::ControllerState before;
    ex::ControllerInputs inputs;
  };
  std::optional<Last> last_;   // the step whose rho, v, w are not computed yet
};

}  // namespace

std::unique_ptr<Component> make_controller_component(const FmuSetup& setup) {
  return std::make_unique<ControllerComponent>(setup.scenario.controller);
}

}  // namespace swarmcheck::fmi
