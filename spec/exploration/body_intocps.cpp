#include "spec/exploration/body_intocps.hpp"

#include <cmath>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {

using P = IntocpsBodyParams;
using S = IntocpsServoParams;

constexpr double kBinaryPi = 3.14159265358979;   // the literal the encoders use

// The table: the FMU's names and value references (thesis-body.md section 2).
constexpr IntocpsBodyParameter plain(std::string_view name, uint32_t vr, double P::*m) {
  return {name, vr, m, -1, -1, nullptr};
}
constexpr IntocpsBodyParameter position(std::string_view name, uint32_t vr, int32_t k) {
  return {name, vr, nullptr, k, -1, nullptr};
}
constexpr IntocpsBodyParameter servo(std::string_view name, uint32_t vr, int32_t side, double S::*m) {
  return {name, vr, nullptr, -1, side, m};
}

constexpr std::array<IntocpsBodyParameter, 45> kParameters{{
    plain("battery_initial_energy", 1, &P::battery_initial_energy),
    plain("individual_sensor_power", 2, &P::individual_sensor_power),
    plain("controller_power", 3, &P::controller_power),
    plain("Battery.powerOn", 4, &P::battery_power_on),
    plain("Battery.powerOff", 5, &P::battery_power_off),
    plain("axle_offset", 6, &P::axle_offset),
    plain("axle_half_width", 7, &P::axle_half_width),
    plain("robot_inertia_without_battery", 8, &P::robot_inertia_without_battery),
    plain("battery_mass", 9, &P::battery_mass),
    plain("battery_length", 10, &P::battery_length),
    plain("battery_width", 11, &P::battery_width),
    plain("battery_cog_offset", 12, &P::battery_cog_offset),
    plain("robot_mass_without_battery", 13, &P::robot_mass_without_battery),
    position("initial_position[0]", 14, 0),
    position("initial_position[1]", 15, 1),
    position("initial_position[2]", 16, 2),
    plain("mu", 17, &P::mu),
    plain("body.R.bladePosition", 18, &P::blade_position),
    plain("encoder_resolution", 19, &P::encoder_resolution),
    plain("encoder_left.Quantisize.lsb", 20, &P::encoder_left_lsb),
    plain("encoder_right.Quantisize.lsb", 21, &P::encoder_right_lsb),
    plain("num_sensors", 22, &P::num_sensors),
    plain("wheel_radius", 23, &P::wheel_radius),
    plain("wheel_thickness", 24, &P::wheel_thickness),
    plain("wheel_material_density", 25, &P::wheel_material_density),
    servo("servo_left.friction.r", 26, 0, &S::friction_r),
    servo("servo_left.inductance.i", 27, 0, &S::inductance_i),
    servo("servo_left.internal_controller.kp", 28, 0, &S::kp),
    servo("servo_left.internal_controller.tauI", 29, 0, &S::tau_i),
    servo("servo_left.motor_constant.r", 30, 0, &S::motor_constant_r),
    servo("servo_left.pwm_to_speed.K", 31, 0, &S::pwm_to_speed_k),
    servo("servo_left.resistance.r", 32, 0, &S::resistance_r),
    servo("servo_left.voltage_limit.maximum", 33, 0, &S::voltage_maximum),
    servo("servo_left.voltage_limit.minimum", 34, 0, &S::voltage_minimum),
    servo("servo_right.friction.r", 35, 1, &S::friction_r),
    servo("servo_right.inductance.i", 36, 1, &S::inductance_i),
    servo("servo_right.internal_controller.kp", 37, 1, &S::kp),
    servo("servo_right.internal_controller.tauI", 38, 1, &S::tau_i),
    servo("servo_right.motor_constant.r", 39, 1, &S::motor_constant_r),
    servo("servo_right.pwm_to_speed.K", 40, 1, &S::pwm_to_speed_k),
    servo("servo_right.resistance.r", 41, 1, &S::resistance_r),
    servo("servo_right.voltage_limit.maximum", 42, 1, &S::voltage_maximum),
    servo("servo_right.voltage_limit.minimum", 43, 1, &S::voltage_minimum),
    plain("wheel_left.R.r", 44, &P::wheel_left_lateral_damping),
    plain("wheel_right.R2.r", 45, &P::wheel_right_lateral_damping),
}};

// A 2x2 matrix times a vector, as the binary sums: (0 + M00 v0) + M01 v1 per row.
std::array<double, 2> times(const Mat2& m, double v0, double v1) {
  return {(0.0 + m[0][0] * v0) + m[0][1] * v1, (0.0 + m[1][0] * v0) + m[1][1] * v1};
}

Mat2 rotation(double theta) {
  const double c = std::cos(theta), s = std::sin(theta);
  return Mat2{{{c, -s}, {s, c}}};
}

// The rate evaluation F at the current states and inputs (thesis-body.md section 6).
void rates(const IntocpsBodyModel& m, IntocpsBodyState& st, double u_left, double u_right) {
  const P& p = m.p;
  const auto& s = st.states;
  auto& r = st.rates;
  const double theta = s[kHeadingChange] + p.initial_position[2];
  const double i_left = s[kFluxLeft] / p.servo_left.inductance_i;
  const double i_right = s[kFluxRight] / p.servo_right.inductance_i;
  const double ui_left = m.pi_integral_gain_left * s[kPiIntegralLeft];
  const double ui_right = m.pi_integral_gain_right * s[kPiIntegralRight];
  const Mat2 rot = rotation(theta);
  st.reported = st.position;
  st.theta = theta;
  // Battery: the energies seen follow the states while the last F left energy in it.
  if (st.battery_remaining > 0) {
    st.controller_energy_seen = s[kControllerEnergy];
    st.sensor_energy_seen = s[kSensorEnergy];
  }
  double remaining = (((p.battery_initial_energy - s[kMotorLeftEnergy]) - s[kMotorRightEnergy]) -
                      st.controller_energy_seen) - st.sensor_energy_seen;
  if (remaining < 0) remaining = 0;
  st.battery_remaining = remaining;
  const double battery = remaining > 0 ? p.battery_power_on : p.battery_power_off;
  r[kHeadingChange] = s[kAngularMomentum] / m.inertia;
  r[kDisplacementX] = m.inv_mass * s[kMomentumX];
  r[kDisplacementY] = m.inv_mass * s[kMomentumY];
  const double friction_x = m.ground_friction * r[kDisplacementX];
  const double friction_y = m.ground_friction * r[kDisplacementY];
  // The motor speeds from the contact velocities of the LAST G (the one-step lag).
  const double omega_left = st.contact[1] / p.wheel_radius;
  const double omega_right = -(st.contact[3] / p.wheel_radius);
  r[kWheelLeftAngle] = omega_left;
  r[kWheelRightAngle] = omega_right;
  r[kPiIntegralLeft] = p.servo_left.pwm_to_speed_k * u_left - omega_left;
  r[kPiIntegralRight] = p.servo_right.pwm_to_speed_k * u_right - omega_right;
  const auto voltage = [&](const S& sv, double error, double integral) {
    double v = sv.kp * error + integral;
    if (v > sv.voltage_maximum) v = sv.voltage_maximum;
    else if (v < sv.voltage_minimum) v = sv.voltage_minimum;
    return v * battery;
  };
  const double v_left = voltage(p.servo_left, r[kPiIntegralLeft], ui_left);
  const double v_right = voltage(p.servo_right, r[kPiIntegralRight], ui_right);
  r[kFluxLeft] = (v_left - p.servo_left.motor_constant_r * omega_left) - p.servo_left.resistance_r * i_left;
  r[kFluxRight] = (v_right - p.servo_right.motor_constant_r * omega_right) - p.servo_right.resistance_r * i_right;
  r[kMotorLeftEnergy] = v_left * i_left;
  r[kMotorRightEnergy] = v_right * i_right;
  const double fl_x = -(p.wheel_left_lateral_damping * st.contact[0]);
  const double fl_y = (p.servo_left.motor_constant_r * i_left - p.servo_left.friction_r * omega_left) / p.wheel_radius;
  const double fr_x = -(p.wheel_right_lateral_damping * st.contact[2]);
  const double fr_y =
      -((p.servo_right.motor_constant_r * i_right - p.servo_right.friction_r * omega_right) / p.wheel_radius);
  const double a = p.axle_offset, b = p.axle_half_width;
  r[kAngularMomentum] = (a * fl_x + (-b) * fl_y) + (a * fr_x + b * fr_y);
  // Rot(theta) as the binary forms it: the inverse of its transpose.
  const Mat2 rot_t{{{rot[0][0], rot[1][0]}, {rot[0][1], rot[1][1]}}};
  const auto force = times(intocps_lu_inverse(rot_t), fl_x + fr_x, fl_y + fr_y);
  r[kMomentumX] = force[0] - friction_x;
  r[kMomentumY] = force[1] - friction_y;
  r[kControllerEnergy] = p.controller_power;
  r[kSensorEnergy] = m.sensor_power;
}

// Encoder count of a wheel angle: rounded half away from zero to whole lsb.
double encoder(double angle, double resolution, double lsb) {
  double q = angle * resolution / (2 * kBinaryPi);
  q = q < 0 ? q - lsb / 2 : q + lsb / 2;
  return q - (q - lsb * std::trunc(q / lsb));
}

// The output evaluation G after a completed RK4 step.
void outputs(const IntocpsBodyModel& m, IntocpsBodyState& st) {
  const P& p = m.p;
  const auto& s = st.states;
  st.position = {s[kDisplacementX] + st.origin[0], s[kDisplacementY] + st.origin[1]};
  IntocpsBodyOutputs& o = st.outputs;
  o.robot_x = st.reported[0];
  o.robot_y = st.reported[1];
  o.robot_theta = st.theta;
  o.wheel_left_rotation = s[kWheelLeftAngle];
  o.wheel_right_rotation = s[kWheelRightAngle];
  o.encoder_left_output = encoder(s[kWheelLeftAngle], p.encoder_resolution, p.encoder_left_lsb);
  o.encoder_right_output = encoder(s[kWheelRightAngle], p.encoder_resolution, p.encoder_right_lsb);
  o.total_energy_used = p.battery_initial_energy - st.battery_remaining;
  // The contact velocities, body frame, from the last F's rates and rotation.
  const auto v = times(intocps_lu_inverse(rotation(st.theta)), st.rates[kDisplacementX], st.rates[kDisplacementY]);
  const double w = st.rates[kHeadingChange];
  const double a = p.axle_offset, b = p.axle_half_width;
  st.contact = {a * w + v[0], (-b) * w + v[1], a * w + v[0], b * w + v[1]};
}

}  // namespace

std::span<const IntocpsBodyParameter> intocps_body_parameters() { return kParameters; }

const IntocpsBodyParameter* find_intocps_body_parameter(std::string_view name) {
  for (const IntocpsBodyParameter& d : kParameters)
    if (d.name == name) return &d;
  return nullptr;
}

double& intocps_parameter_ref(IntocpsBodyParams& p, const IntocpsBodyParameter& d) {
  if (d.initial_position_index >= 0) return p.initial_position[static_cast<std::size_t>(d.initial_position_index)];
  if (d.servo >= 0) {
    IntocpsServoParams* servo = d.servo == 0 ? &p.servo_left : &p.servo_right;
    return servo->*(d.servo_member);
  }
  return p.*(d.member);
}

double intocps_parameter_value(const IntocpsBodyParams& p, const IntocpsBodyParameter& d) {
  IntocpsBodyParams copy = p;
  return intocps_parameter_ref(copy, d);
}

IntocpsBodyParams scenario_intocps_params() {
  IntocpsBodyParams p;
  p.battery_initial_energy = 1e21;
  return p;
}

IntocpsBodyModel intocps_body_model(const IntocpsBodyParams& p) {
  IntocpsBodyModel m;
  m.p = p;
  m.inv_mass = 1.0 / (p.robot_mass_without_battery + p.battery_mass);
  m.inertia = p.robot_inertia_without_battery +
              ((((p.battery_mass / 12) * (p.battery_length * p.battery_length)) * (p.battery_width * p.battery_width)) +
               p.battery_mass * (p.battery_cog_offset * p.battery_cog_offset));
  m.ground_friction = ((p.robot_mass_without_battery * p.axle_offset) / p.blade_position) * p.mu +
                      ((p.battery_mass * p.battery_cog_offset) / p.blade_position) * p.mu;
  const double n = p.num_sensors;
  const bool counted = n == 1 || n == 2 || n == 3 || n == 4 || n == 5;
  m.sensor_power = (counted ? n : 0.0) * p.individual_sensor_power;
  m.pi_integral_gain_left = p.servo_left.kp / p.servo_left.tau_i;
  m.pi_integral_gain_right = p.servo_right.kp / p.servo_right.tau_i;
  return m;
}

Mat2 intocps_lu_inverse(const Mat2& in) {
  const bool swap = std::fabs(in[1][0]) > std::fabs(in[0][0]);
  const Mat2 a = swap ? Mat2{{in[1], in[0]}} : in;
  const double piv0 = a[0][0];
  const double u = a[0][1] / piv0;
  const double l = a[1][0];
  const double piv1 = a[1][1] - l * u;
  Mat2 x{};
  for (int k = 0; k < 2; ++k) {
    double e0 = k == 0 ? 1.0 : 0.0, e1 = k == 1 ? 1.0 : 0.0;
    if (swap) std::swap(e0, e1);
    const double y0 = e0 / piv0;
    const double y1 = (e1 - l * y0) / piv1;
    x[1][static_cast<std::size_t>(k)] = y1;
    x[0][static_cast<std::size_t>(k)] = y0 - u * y1;
  }
  return x;
}

IntocpsBodyState intocps_body_setup(double start_time_s) {
  const IntocpsBodyModel defaults = intocps_body_model(IntocpsBodyParams{});
  IntocpsBodyState s{};
  s.solver_time_s = start_time_s;
  s.origin = {defaults.p.initial_position[0], defaults.p.initial_position[1]};
  rates(defaults, s, 0.0, 0.0);
  outputs(defaults, s);
  return s;
}

IntocpsBodyState intocps_body_initialised(double start_time_s, double x0_m, double y0_m) {
  IntocpsBodyState s = intocps_body_setup(start_time_s);
  s.origin = {x0_m, y0_m};
  return s;
}

void intocps_body_rk4_step(const IntocpsBodyModel& m, IntocpsBodyState& st, double servo_left, double servo_right) {
  constexpr double h = kIntocpsSolverStep_s;
  const std::array<double, kIntocpsStates> q0 = st.states;
  std::array<double, kIntocpsStates> k1, k2, k3, k4;
  for (int i = 0; i < kIntocpsStates; ++i) k1[i] = st.rates[i] * h;
  for (int i = 0; i < kIntocpsStates; ++i) st.states[i] = q0[i] + k1[i] / 2;
  rates(m, st, servo_left, servo_right);
  for (int i = 0; i < kIntocpsStates; ++i) k2[i] = st.rates[i] * h;
  for (int i = 0; i < kIntocpsStates; ++i) st.states[i] = q0[i] + k2[i] / 2;
  rates(m, st, servo_left, servo_right);
  for (int i = 0; i < kIntocpsStates; ++i) k3[i] = st.rates[i] * h;
  for (int i = 0; i < kIntocpsStates; ++i) st.states[i] = q0[i] + k3[i];
  rates(m, st, servo_left, servo_right);
  for (int i = 0; i < kIntocpsStates; ++i) k4[i] = st.rates[i] * h;
  for (int i = 0; i < kIntocpsStates; ++i)
    st.states[i] = q0[i] + (((((k1[i] + k2[i]) + k2[i]) + k3[i]) + k3[i]) + k4[i]) * (1.0 / 6.0);
  rates(m, st, servo_left, servo_right);
  st.solver_time_s = st.solver_time_s + h;
  outputs(m, st);
}

IntocpsSolverSteps intocps_solver_steps(double solver_time_s, double t_s, double h_s) {
  IntocpsSolverSteps n{0, solver_time_s};
  if (h_s == 0) return n;
  while (n.clock_after_s < t_s + h_s) {
    n.clock_after_s = n.clock_after_s + kIntocpsSolverStep_s;
    ++n.count;
  }
  return n;
}

int32_t intocps_body_do_step(const IntocpsBodyModel& m, IntocpsBodyState& s, double servo_left, double servo_right,
                             double t_s, double h_s) {
  int32_t n = 0;
  if (h_s == 0) return n;
  while (s.solver_time_s < t_s + h_s) {
    intocps_body_rk4_step(m, s, servo_left, servo_right);
    ++n;
  }
  return n;
}

IntocpsBodyState intocps_body_step(const IntocpsBodyModel& m, const IntocpsBodyState& s, double servo_left,
                                   double servo_right, double t_s, double h_s) {
  IntocpsBodyState next = s;
  intocps_body_do_step(m, next, servo_left, servo_right, t_s, h_s);
  return next;
}

}  // namespace swarmcheck::exploration
