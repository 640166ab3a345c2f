#include "spec/exploration/controller.hpp"

#include <cmath>
#include <numbers>

#include "spec/util/demand.hpp"

namespace swarmcheck::exploration {
namespace {

constexpr double kPi = std::numbers::pi;

ControllerState hold(ControllerState s, int32_t maneuver, int32_t output) {
  s.maneuver = maneuver;
  s.on_destination_output = output;
  s.servo_left = 0.0;
  s.servo_right = 0.0;
  return s;
}

// Bearing error: the waypoint's direction minus the heading theta + pi/2, wrapped.
double bearing_error(double dx, double dy, double theta_rad) {
  return wrap_angle(std::atan2(dy, dx) - theta_rad - kPi / 2);
}

}  // namespace

ControllerState initial_controller() { return ControllerState{1, 1, 0.0, 0.0, 0.0}; }

double wrap_angle(double x_rad) {
  double r = std::remainder(x_rad, 2 * kPi);
  if (r <= -kPi) r += 2 * kPi;
  return r;
}

double saturate_servo(double u) {
  if (std::isnan(u)) return 0.0;
  if (u > 1.0) return 1.0;
  if (u < -1.0) return -1.0;
  return u;
}

double thesis_clamp(double u) {
  if (u > 1) u = 1;
  else if (u < -1) u = -1;
  return u;
}

ControllerState controller_step(const RobotParams& rp, const ControllerState& s,
                                const ControllerInputs& in) {
  SWARM_DEMAND(s.maneuver == 1 || s.maneuver == 2);
  SWARM_DEMAND(s.on_destination_output == 0 || s.on_destination_output == 1);
  if (s.on_destination_output == 1)
    return in.on_destination_input == 1 ? hold(s, 1, 0) : hold(s, s.maneuver, 1);
  double dx = in.waypoint[0] - in.pose.x_m;
  double dy = in.waypoint[1] - in.pose.y_m;
  if (std::fabs(dx) + std::fabs(dy) < rp.tolerance_m) return hold(s, 1, 1);

  ControllerState n = s;
  if (n.maneuver == 1) {
    // The atan2 fix: near-zero deltas would flip atan2's sign as the body jitters in place.
    if (!(std::fabs(dx) < rp.tolerance_m && std::fabs(dy) < rp.tolerance_m)) {
      if (std::fabs(dx) < rp.tolerance_m) dx = 0;
      if (std::fabs(dy) < rp.tolerance_m) dy = 0;
    }
    n.beta_rad = bearing_error(dx, dy, in.pose.theta_rad);
    if (std::fabs(n.beta_rad) < rp.orient_tolerance_rad) n.maneuver = 2;
  } else {
    n.beta_rad = bearing_error(dx, dy, in.pose.theta_rad);
    if (std::fabs(n.beta_rad) > rp.reorient_rad) n.maneuver = 1;
  }

  double v = 0.0;
  if (n.maneuver == 2) {
    const double rho = std::sqrt(dx * dx + dy * dy);
    v = rho * rp.k_v * (rho * rho * std::cos(n.beta_rad) + n.beta_rad * std::sin(n.beta_rad));
  }
  const double w = -rp.k_beta * n.beta_rad;
  const double r = rp.wheel_radius_m;
  const double l = 2 * rp.half_axle_m;
  n.servo_left = saturate_servo((1 / r) * v + (l / (2 * r)) * w);
  n.servo_right = saturate_servo(-((1 / r) * v - (l / (2 * r)) * w));
  return n;
}

}  // namespace swarmcheck::exploration
