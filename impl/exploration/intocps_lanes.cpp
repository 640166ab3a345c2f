#include "impl/exploration/intocps_lanes.hpp"

#include <cmath>

// Every function here that takes or returns a Lane by value has internal linkage, so the AVX
// calling convention GCC warns about (-Wpsabi) never crosses an object file.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace swarmcheck::impl::exploration {
namespace {

namespace ex = swarmcheck::exploration;
using P = ex::IntocpsBodyParams;

constexpr double kBinaryPi = 3.14159265358979;   // the literal the encoders use

Lane splat(double v) { return Lane{v, v, v, v}; }

Lane abs_lane(const Lane& v) {
  return reinterpret_cast<Lane>(reinterpret_cast<LaneMask>(v) & 0x7fffffffffffffffLL);
}

// mask ? a : b, lane by lane (no arithmetic: -0.0 and NaN pass as they are).
Lane pick(const LaneMask& mask, const Lane& a, const Lane& b) {
  return reinterpret_cast<Lane>((reinterpret_cast<LaneMask>(a) & mask) | (reinterpret_cast<LaneMask>(b) & ~mask));
}

// The binary's 2x2 inverse (spec intocps_lu_inverse), lane by lane, and the product with (v0, v1)
// summed as (0 + M00 v0) + M01 v1 per row.
struct LaneMat {
  Lane m00, m01, m10, m11;
};

LaneMat lu_inverse(const LaneMat& in) {
  const LaneMask swap = abs_lane(in.m10) > abs_lane(in.m00);
  const Lane a00 = pick(swap, in.m10, in.m00), a01 = pick(swap, in.m11, in.m01);
  const Lane a10 = pick(swap, in.m00, in.m10), a11 = pick(swap, in.m01, in.m11);
  const Lane piv0 = a00;
  const Lane u = a01 / piv0;
  const Lane l = a10;
  const Lane piv1 = a11 - l * u;
  const Lane one = splat(1.0), zero = splat(0.0);
  LaneMat x;
  {   // column 0: e = (1, 0), permuted
    const Lane e0 = pick(swap, zero, one), e1 = pick(swap, one, zero);
    const Lane y0 = e0 / piv0;
    const Lane y1 = (e1 - l * y0) / piv1;
    x.m10 = y1;
    x.m00 = y0 - u * y1;
  }
  {   // column 1: e = (0, 1), permuted
    const Lane e0 = pick(swap, one, zero), e1 = pick(swap, zero, one);
    const Lane y0 = e0 / piv0;
    const Lane y1 = (e1 - l * y0) / piv1;
    x.m11 = y1;
    x.m01 = y0 - u * y1;
  }
  return x;
}

void times(const LaneMat& m, const Lane& v0, const Lane& v1, Lane& out0, Lane& out1) {
  out0 = (splat(0.0) + m.m00 * v0) + m.m01 * v1;
  out1 = (splat(0.0) + m.m10 * v0) + m.m11 * v1;
}

// The rate evaluation F (spec rates()), four robots at once.
void rates(const IntocpsLaneModel& lm, IntocpsLanes& b, const Lane& u_left, const Lane& u_right) {
  const ex::IntocpsBodyModel& m = lm.model;
  const P& p = m.p;
  const Lane theta = b.s[ex::kHeadingChange] + p.initial_position[2];
  const Lane i_left = b.s[ex::kFluxLeft] / p.servo_left.inductance_i;
  const Lane i_right = b.s[ex::kFluxRight] / p.servo_right.inductance_i;
  const Lane ui_left = m.pi_integral_gain_left * b.s[ex::kPiIntegralLeft];
  const Lane ui_right = m.pi_integral_gain_right * b.s[ex::kPiIntegralRight];
  Lane c, s;
  for (int k = 0; k < kLanes; ++k) {
    c[k] = std::cos(theta[k]);
    s[k] = std::sin(theta[k]);
  }
  b.reported[0] = b.position[0];
  b.reported[1] = b.position[1];
  b.theta = theta;
  b.cos_theta = c;
  b.sin_theta = s;
  const LaneMask had_energy = b.remaining > 0;
  b.controller_energy_seen = pick(had_energy, b.s[ex::kControllerEnergy], b.controller_energy_seen);
  b.sensor_energy_seen = pick(had_energy, b.s[ex::kSensorEnergy], b.sensor_energy_seen);
  Lane remaining = (((p.battery_initial_energy - b.s[ex::kMotorLeftEnergy]) - b.s[ex::kMotorRightEnergy]) -
                    b.controller_energy_seen) - b.sensor_energy_seen;
  remaining = pick(remaining < 0, splat(0.0), remaining);
  b.remaining = remaining;
  const Lane battery = pick(remaining > 0, splat(p.battery_power_on), splat(p.battery_power_off));
  Lane* r = b.rate;
  r[ex::kHeadingChange] = b.s[ex::kAngularMomentum] / m.inertia;
  r[ex::kDisplacementX] = m.inv_mass * b.s[ex::kMomentumX];
  r[ex::kDisplacementY] = m.inv_mass * b.s[ex::kMomentumY];
  const Lane friction_x = m.ground_friction * r[ex::kDisplacementX];
  const Lane friction_y = m.ground_friction * r[ex::kDisplacementY];
  const Lane omega_left = b.contact[1] / p.wheel_radius;
  const Lane omega_right = -(b.contact[3] / p.wheel_radius);
  r[ex::kWheelLeftAngle] = omega_left;
  r[ex::kWheelRightAngle] = omega_right;
  r[ex::kPiIntegralLeft] = p.servo_left.pwm_to_speed_k * u_left - omega_left;
  r[ex::kPiIntegralRight] = p.servo_right.pwm_to_speed_k * u_right - omega_right;
  const auto voltage = [&](const ex::IntocpsServoParams& sv, const Lane& error, const Lane& integral) {
    Lane v = sv.kp * error + integral;
    const Lane above = splat(sv.voltage_maximum), below = splat(sv.voltage_minimum);
    v = pick(v > above, above, pick(v < below, below, v));
    return v * battery;
  };
  const Lane v_left = voltage(p.servo_left, r[ex::kPiIntegralLeft], ui_left);
  const Lane v_right = voltage(p.servo_right, r[ex::kPiIntegralRight], ui_right);
  r[ex::kFluxLeft] = (v_left - p.servo_left.motor_constant_r * omega_left) - p.servo_left.resistance_r * i_left;
  r[ex::kFluxRight] = (v_right - p.servo_right.motor_constant_r * omega_right) - p.servo_right.resistance_r * i_right;
  r[ex::kMotorLeftEnergy] = v_left * i_left;
  r[ex::kMotorRightEnergy] = v_right * i_right;
  const Lane fl_x = -(p.wheel_left_lateral_damping * b.contact[0]);
  const Lane fl_y = (p.servo_left.motor_constant_r * i_left - p.servo_left.friction_r * omega_left) / p.wheel_radius;
  const Lane fr_x = -(p.wheel_right_lateral_damping * b.contact[2]);
  const Lane fr_y =
      -((p.servo_right.motor_constant_r * i_right - p.servo_right.friction_r * omega_right) / p.wheel_radius);
  const double a = p.axle_offset, bw = p.axle_half_width;
  r[ex::kAngularMomentum] = (a * fl_x + (-bw) * fl_y) + (a * fr_x + bw * fr_y);
  // Rot(theta) as the inverse of its transpose: [[c, s], [-s, c]].
  const LaneMat rot_t{c, s, -s, c};
  Lane f0, f1;
  times(lu_inverse(rot_t), fl_x + fr_x, fl_y + fr_y, f0, f1);
  r[ex::kMomentumX] = f0 - friction_x;
  r[ex::kMomentumY] = f1 - friction_y;
  r[ex::kControllerEnergy] = splat(p.controller_power);
  r[ex::kSensorEnergy] = splat(m.sensor_power);
}

// The output evaluation G (spec outputs()) without the outputs: POS, then the contact velocities
// from the last F's rates and rotation.
void positions_and_contacts(const IntocpsLaneModel& lm, IntocpsLanes& b) {
  const P& p = lm.model.p;
  b.position[0] = b.s[ex::kDisplacementX] + b.origin[0];
  b.position[1] = b.s[ex::kDisplacementY] + b.origin[1];
  const LaneMat rot{b.cos_theta, -b.sin_theta, b.sin_theta, b.cos_theta};
  Lane v0, v1;
  times(lu_inverse(rot), b.rate[ex::kDisplacementX], b.rate[ex::kDisplacementY], v0, v1);
  const Lane w = b.rate[ex::kHeadingChange];
  const double a = p.axle_offset, bw = p.axle_half_width;
  b.contact[0] = a * w + v0;
  b.contact[1] = (-bw) * w + v1;
  b.contact[2] = a * w + v0;
  b.contact[3] = bw * w + v1;
}

double encoder(double angle, double resolution, double lsb) {
  double q = angle * resolution / (2 * kBinaryPi);
  q = q < 0 ? q - lsb / 2 : q + lsb / 2;
  return q - (q - lsb * std::trunc(q / lsb));
}

}  // namespace

IntocpsLaneModel::IntocpsLaneModel(const ex::IntocpsBodyModel& m) : model(m) {}

void put_lane(IntocpsLanes& b, int k, const ex::IntocpsBodyState& s) {
  for (int i = 0; i < ex::kIntocpsStates; ++i) {
    b.s[i][k] = s.states[static_cast<std::size_t>(i)];
    b.rate[i][k] = s.rates[static_cast<std::size_t>(i)];
  }
  for (int i = 0; i < 4; ++i) b.contact[i][k] = s.contact[static_cast<std::size_t>(i)];
  for (int i = 0; i < 2; ++i) {
    b.position[i][k] = s.position[static_cast<std::size_t>(i)];
    b.reported[i][k] = s.reported[static_cast<std::size_t>(i)];
    b.origin[i][k] = s.origin[static_cast<std::size_t>(i)];
  }
  b.theta[k] = s.theta;
  b.cos_theta[k] = std::cos(s.theta);
  b.sin_theta[k] = std::sin(s.theta);
  b.remaining[k] = s.battery_remaining;
  b.controller_energy_seen[k] = s.controller_energy_seen;
  b.sensor_energy_seen[k] = s.sensor_energy_seen;
}

ex::IntocpsBodyState get_lane(const IntocpsLaneModel& lm, const IntocpsLanes& b, int k, double solver_time_s) {
  const P& p = lm.model.p;
  ex::IntocpsBodyState s{};
  for (int i = 0; i < ex::kIntocpsStates; ++i) {
    s.states[static_cast<std::size_t>(i)] = b.s[i][k];
    s.rates[static_cast<std::size_t>(i)] = b.rate[i][k];
  }
  for (int i = 0; i < 4; ++i) s.contact[static_cast<std::size_t>(i)] = b.contact[i][k];
  for (int i = 0; i < 2; ++i) {
    s.position[static_cast<std::size_t>(i)] = b.position[i][k];
    s.reported[static_cast<std::size_t>(i)] = b.reported[i][k];
    s.origin[static_cast<std::size_t>(i)] = b.origin[i][k];
  }
  s.theta = b.theta[k];
  s.battery_remaining = b.remaining[k];
  s.controller_energy_seen = b.controller_energy_seen[k];
  s.sensor_energy_seen = b.sensor_energy_seen[k];
  s.solver_time_s = solver_time_s;
  ex::IntocpsBodyOutputs& o = s.outputs;
  o.robot_x = s.reported[0];
  o.robot_y = s.reported[1];
  o.robot_theta = s.theta;
  o.wheel_left_rotation = s.states[ex::kWheelLeftAngle];
  o.wheel_right_rotation = s.states[ex::kWheelRightAngle];
  o.encoder_left_output = encoder(s.states[ex::kWheelLeftAngle], p.encoder_resolution, p.encoder_left_lsb);
  o.encoder_right_output = encoder(s.states[ex::kWheelRightAngle], p.encoder_resolution, p.encoder_right_lsb);
  o.total_energy_used = p.battery_initial_energy - s.battery_remaining;
  return s;
}

std::array<double, 3> lane_pose(const IntocpsLanes& b, int k) { return {b.reported[0][k], b.reported[1][k], b.theta[k]}; }

void intocps_lanes_rk4(const IntocpsLaneModel& m, IntocpsLanes& b, const Lane& left, const Lane& right,
                       int32_t count) {
  constexpr double h = ex::kIntocpsSolverStep_s;
  constexpr int n = ex::kIntocpsStates;
  for (int32_t step = 0; step < count; ++step) {
    Lane q0[n], k1[n], k2[n], k3[n];
    for (int i = 0; i < n; ++i) q0[i] = b.s[i];
    for (int i = 0; i < n; ++i) k1[i] = b.rate[i] * h;
    for (int i = 0; i < n; ++i) b.s[i] = q0[i] + k1[i] / 2;
    rates(m, b, left, right);
    for (int i = 0; i < n; ++i) k2[i] = b.rate[i] * h;
    for (int i = 0; i < n; ++i) b.s[i] = q0[i] + k2[i] / 2;
    rates(m, b, left, right);
    for (int i = 0; i < n; ++i) k3[i] = b.rate[i] * h;
    for (int i = 0; i < n; ++i) b.s[i] = q0[i] + k3[i];
    rates(m, b, left, right);
    for (int i = 0; i < n; ++i) {
      const Lane k4 = b.rate[i] * h;
      b.s[i] = q0[i] + (((((k1[i] + k2[i]) + k2[i]) + k3[i]) + k3[i]) + k4) * (1.0 / 6.0);
    }
    rates(m, b, left, right);
    positions_and_contacts(m, b);
  }
}

}  // namespace swarmcheck::impl::exploration
