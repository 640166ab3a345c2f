// The intocps Body FMU: thesis A's 20-sim Body_Block (spec/exploration/body_intocps.hpp) for one
// robot, with the Body_Block FMU's variable names (its 45 parameters as `servo_left.friction.r`,
// `initial_position[0]`, ...; inputs servo_left_input, servo_right_input; its nine outputs), so
// that it stands in for Body_Block1..4.fmu in the thesis's multi-model, and runs the spec step the
// model and the library run: the same bits at every output (tests/fmi/intocps_body_fmu_test.cpp).
//
// What differs from the 20-sim binary, on purpose: every instance has its own memory (no global
// state, so canBeInstantiatedOnlyOncePerProcess is false); parameters written before
// fmi2SetupExperiment are kept (the binary resets them there); the stop time is not enforced. Right
// after initialisation robot_x and robot_y read 0 and robot_theta the default heading, as the
// binary's do (body_intocps.hpp): the run's parameters take effect from the first step.
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

#include "fmi/fmu/kinds.hpp"
#include "spec/exploration/body_intocps.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

// The model description's text for a parameter (thesis-body.md section 2).
std::string describe_parameter(const ex::IntocpsBodyParameter& d) {
  struct Text {
    std::string_view name;
    const char* text;
  };
  static constexpr Text kPlain[] = {
      {"battery_initial_energy", "battery capacity E0, J"},
      {"individual_sensor_power", "power of one line-follower sensor P_s, W"},
      {"controller_power", "controller power P_c, W"},
      {"Battery.powerOn", "voltage factor while the battery has energy"},
      {"Battery.powerOff", "voltage factor once the battery is empty"},
      {"axle_offset", "reported point P ahead of the axle a, m"},
      {"axle_half_width", "half track b, m"},
      {"robot_inertia_without_battery", "chassis inertia J_r, kg m^2"},
      {"battery_mass", "battery mass m_b, kg"},
      {"battery_length", "battery length l_b, m"},
      {"battery_width", "battery width w_b, m"},
      {"battery_cog_offset", "battery centre of gravity offset o_b, m"},
      {"robot_mass_without_battery", "chassis mass m_r, kg"},
      {"initial_position[0]", "start x of P, m"},
      {"initial_position[1]", "start y of P, m"},
      {"initial_position[2]", "start heading, rad"},
      {"mu", "viscous ground-friction coefficient, N s/m^2"},
      {"body.R.bladePosition", "blade position l_blade, m"},
      {"encoder_resolution", "encoder counts per wheel revolution"},
      {"encoder_left.Quantisize.lsb", "left encoder quantum, counts"},
      {"encoder_right.Quantisize.lsb", "right encoder quantum, counts"},
      {"num_sensors", "line-follower sensors drawing power (1..5; other values: none)"},
      {"wheel_radius", "wheel radius r, m"},
      {"wheel_thickness", "wheel thickness, m (unused by the model)"},
      {"wheel_material_density", "wheel material density, kg/m^3 (unused by the model)"},
      {"wheel_left.R.r", "left wheel lateral damping d, N s/m"},
      {"wheel_right.R2.r", "right wheel lateral damping d, N s/m"},
  };
  static constexpr Text kServo[] = {
      {"friction.r", "motor viscous friction f, N m s/rad"},
      {"inductance.i", "winding inductance L, H"},
      {"internal_controller.kp", "PI speed loop gain k_p, V s/rad"},
      {"internal_controller.tauI", "PI speed loop integral time tau_I, s"},
      {"motor_constant.r", "torque and back-EMF constant k_m, N m/A"},
      {"pwm_to_speed.K", "wheel speed per unit servo input K_s, rad/s"},
      {"resistance.r", "winding resistance R_a, Ohm"},
      {"voltage_limit.maximum", "PI output upper clamp, V"},
      {"voltage_limit.minimum", "PI output lower clamp, V"},
  };
  if (d.servo >= 0) {
    const std::string_view member = d.name.substr(d.name.find('.') + 1);
    for (const Text& t : kServo)
      if (t.name == member) return std::string(d.servo == 0 ? "left" : "right") + " servo: " + t.text;
  }
  for (const Text& t : kPlain)
    if (t.name == d.name) return t.text;
  return std::string("Body_Block parameter ") + std::string(d.name);
}

class IntocpsBodyComponent final : public Component {
 public:
  // `start`: the parameters' start values (the scenario's body with robot 1's position, or the
  // Body_Block's own defaults for the thesis interface).
  explicit IntocpsBodyComponent(const ex::IntocpsBodyParams& start) : Component("body"), start_(start) {
    for (const ex::IntocpsBodyParameter& d : ex::intocps_body_parameters())
      table_.bind_named(ex::intocps_parameter_ref(params_, d), std::string(d.name), Role::parameter,
                        describe_parameter(d));
    table_.bind_named(in_[0], "servo_left_input", Role::input, "left servo input u_L (not clamped; 1 = K_s rad/s)");
    table_.bind_named(in_[1], "servo_right_input", Role::input,
                      "right servo input u_R (mounted mirrored: u_R > 0 drives the right wheel backward)");
    table_.bind_named(out_.robot_x, "robot_x", Role::output, "x of P, m, as it was one solver step (1 ms) ago");
    table_.bind_named(out_.robot_y, "robot_y", Role::output, "y of P, m, as it was one solver step (1 ms) ago");
    table_.bind_named(out_.robot_theta, "robot_theta", Role::output, "heading, rad (unwrapped)");
    table_.bind_named(robot_z_, "robot_z", Role::output, "z of P, m (always 0)");
    table_.bind_named(out_.wheel_left_rotation, "wheel_left_rotation", Role::output, "left wheel angle, rad");
    table_.bind_named(out_.wheel_right_rotation, "wheel_right_rotation", Role::output, "right wheel angle, rad");
    table_.bind_named(out_.encoder_left_output, "encoder_left_output", Role::output, "left encoder, counts");
    table_.bind_named(out_.encoder_right_output, "encoder_right_output", Role::output, "right encoder, counts");
    table_.bind_named(out_.total_energy_used, "total_energy_used", Role::output, "energy drawn from the battery, J");
  }

  void defaults() override {
    params_ = start_;
    in_ = {0.0, 0.0};
    start_time_s_ = 0.0;
    state_ = ex::intocps_body_setup(0.0);
    out_ = state_.outputs;
    robot_z_ = 0.0;
  }

  void start_at(double t_s) override { start_time_s_ = t_s; }

  void initialize() override {
    try {
      ex::validate_intocps_params(params_);
    } catch (const InputError& e) {
      throw FmuError(std::string("the Body_Block's parameters: ") + e.what());
    }
    model_ = ex::intocps_body_model(params_);
    state_ = ex::intocps_body_initialised(start_time_s_, params_.initial_position[0], params_.initial_position[1]);
    out_ = state_.outputs;
  }

  void step(double t_s, double h_s) override {
    // The binary computes whatever its inputs are; a NaN would silently poison all 16 states.
    if (std::isnan(in_[0]) || std::isnan(in_[1]))
      throw FmuError("servo_left_input and servo_right_input must be numbers, got NaN");
    ex::intocps_body_do_step(model_, state_, in_[0], in_[1], t_s, h_s);
    out_ = state_.outputs;
  }

 protected:
  // The variables hold the parameters, inputs and outputs; the body's memory comes after them.
  void save_extra(std::vector<uint8_t>& out) const override {
    put_state_u64(out, std::bit_cast<uint64_t>(start_time_s_));
    const auto put_all = [&](const auto& values) {
      for (const double v : values) put_state_u64(out, std::bit_cast<uint64_t>(v));
    };
    put_all(state_.states);
    put_all(state_.rates);
    put_all(state_.contact);
    put_all(state_.position);
    put_all(state_.reported);
    put_all(std::array{state_.theta, state_.battery_remaining, state_.controller_energy_seen,
                       state_.sensor_energy_seen, state_.solver_time_s});
    put_all(state_.origin);
  }

  void restore_extra(std::span<const uint8_t>& in) override {
    const auto take = [&] { return std::bit_cast<double>(take_state_u64(in)); };
    const auto take_all = [&](auto& values) {
      for (double& v : values) v = take();
    };
    const double start = take();
    ex::IntocpsBodyState s{};
    take_all(s.states);
    take_all(s.rates);
    take_all(s.contact);
    take_all(s.position);
    take_all(s.reported);
    std::array<double, 5> scalars{};
    take_all(scalars);
    s.theta = scalars[0];
    s.battery_remaining = scalars[1];
    s.controller_energy_seen = scalars[2];
    s.sensor_energy_seen = scalars[3];
    s.solver_time_s = scalars[4];
    take_all(s.origin);
    s.outputs = out_;
    start_time_s_ = start;
    state_ = s;
    model_ = ex::intocps_body_model(params_);
  }

 private:
  ex::IntocpsBodyParams start_;
  ex::IntocpsBodyParams params_{};
  std::array<double, 2> in_{};
  ex::IntocpsBodyOutputs out_{};
  double robot_z_ = 0.0;
  double start_time_s_ = 0.0;
  ex::IntocpsBodyModel model_ = ex::intocps_body_model(ex::IntocpsBodyParams{});
  ex::IntocpsBodyState state_{};
};

}  // namespace

// The start values: the Body_Block's own defaults for the thesis interface (its multi-model sets
// the position and the battery); the scenario's body and robot 1's start otherwise.
std::unique_ptr<Component> make_intocps_body_component(const FmuSetup& setup) {
  ex::IntocpsBodyParams start;
  if (setup.interface == Interface::swarmcheck) {
    start = setup.scenario.body.intocps;
    if (!setup.scenario.robots.empty()) {
      start.initial_position[0] = setup.scenario.robots[0][0];
      start.initial_position[1] = setup.scenario.robots[0][1];
    }
  }
  return std::make_unique<IntocpsBodyComponent>(start);
}

}  // namespace swarmcheck::fmi
