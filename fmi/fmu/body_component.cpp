// The Body FMU: spec body_step (the INTO-CPS line follower Body_Block's steady state) for one
// robot; its outputs are its state.
#include <bit>
#include <cmath>
#include <cstdint>

#include "fmi/fmu/kinds.hpp"
#include "spec/exploration/body.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

class BodyComponent final : public Component {
 public:
  BodyComponent() : Component("body") {
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

  void step(double /*t_s*/, double h_s) override {
    if (std::isnan(in_.servo_left_input) || std::isnan(in_.servo_right_input))
      throw FmuError("servo_left_input and servo_right_input must be numbers, got NaN");
    if (ex::body_stays({out_.robot_x, out_.robot_y, out_.robot_theta}, in_.servo_left_input, in_.servo_right_input))
      return;   // body_step would return the same bits
    ex::RobotParams rp;
    rp.wheel_radius_m = params_.wheel_radius;
    rp.motor_gain_rad_per_s = params_.motor_gain;
    rp.half_axle_m = params_.half_axle;
    // The heading of the step before is kept, as the library's master keeps it: heading_of of the
    // same double is the same bits, and a straight drive then needs no trigonometry.
    const ex::BodyState pose{out_.robot_x, out_.robot_y, out_.robot_theta};
    if (std::bit_cast<uint64_t>(pose.theta_rad) != std::bit_cast<uint64_t>(heading_theta_)) {
      heading_ = ex::heading_of(pose.theta_rad);
      heading_theta_ = pose.theta_rad;
    }
    const ex::BodyStep next =
        ex::body_step_with_heading(rp, pose, heading_, in_.servo_left_input, in_.servo_right_input, h_s);
    out_ = {next.state.x_m, next.state.y_m, next.state.theta_rad};
    heading_ = next.heading;
    heading_theta_ = next.state.theta_rad;
  }

 private:
  BodyParameters params_{};
  BodyInputs in_{};
  BodyOutputs out_{};
  ex::Heading heading_ = ex::heading_of(0.0);   // heading_of(heading_theta_)
  double heading_theta_ = 0.0;
};

}  // namespace

std::unique_ptr<Component> make_body_component(const FmuSetup&) { return std::make_unique<BodyComponent>(); }

}  // namespace swarmcheck::fmi
