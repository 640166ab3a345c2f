// The Body FMU: spec body_step (the INTO-CPS line follower Body_Block's steady state) for one
// robot; its outputs are its state.
#include <cmath>

#include "fmi/fmu/kinds.hpp"
#include "spec/exploration/body.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

class BodyComponent final : public Component {
 public:
  BodyComponent() {
    table_.bind(params_, Role::parameter);
    table_.bind(in_, Role::input);
    table_.bind(out_, Role::output);
  }

  void defaults() override {
    const ex::RobotParams rp;
    params_ = {0.5, 0.5, 0.0, rp.wheel_radius_m, rp.motor_gain_rad_per_s, rp.half_axle_m};
    in_ = {0.0, 0.0};
    out_ = {params_.x0, params_.y0, params_.theta0};
  }

  void initialize() override {
    for (const double v : {params_.x0, params_.y0, params_.theta0, params_.wheel_radius, params_.motor_gain,
                           params_.half_axle})
      if (!std::isfinite(v)) throw FmuError("the Body's parameters must be finite");
    if (!(params_.half_axle > 0)) throw FmuError("half_axle must be > 0");
    out_ = {params_.x0, params_.y0, params_.theta0};
  }

  void step(double h_s) override {
    if (std::isnan(in_.servo_left_input) || std::isnan(in_.servo_right_input))
      throw FmuError("servo_left_input and servo_right_input must be numbers, got NaN");
    ex::RobotParams rp;
    rp.wheel_radius_m = params_.wheel_radius;
    rp.motor_gain_rad_per_s = params_.motor_gain;
    rp.half_axle_m = params_.half_axle;
    const ex::BodyState next =
        ex::body_step(rp, {out_.robot_x, out_.robot_y, out_.robot_theta}, in_.servo_left_input, in_.servo_right_input, h_s);
    out_ = {next.x_m, next.y_m, next.theta_rad};
  }

 private:
  BodyParameters params_{};
  BodyInputs in_{};
  BodyOutputs out_{};
};

}  // namespace

std::unique_ptr<Component> make_body_component(const FmuSetup&) { return std::make_unique<BodyComponent>(); }

}  // namespace swarmcheck::fmi
