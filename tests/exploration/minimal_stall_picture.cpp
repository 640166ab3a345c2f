// minimal_stall_picture OUT.svg: the README's picture of thesis A's minimal stall case (start
// (5.95, 5.937), heading -0.25, waypoint (6, 6), steps of 0.1 s) on the 20-sim body, before and
// after the fix of spec/SPEC.md section 8. Before: swarmcheck's previous controller, written out
// here as it was (every orienting step re-reads the bearing from the reported point, through the
// atan2 fix whose deadband is the arrival tolerance); it turns back and forth for ever. After:
// today's controller (spec/exploration/robot.hpp, as the model and the library run it); it
// arrives. Built by `make pictures` only (EXCLUDE_FROM_ALL).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "spec/exploration/robot.hpp"
#include "spec/exploration/scenario.hpp"

using namespace swarmcheck::exploration;
namespace num = swarmcheck::num;
using C = num::Concrete;

namespace {

constexpr Point_m kStart{5.95, 5.937};
constexpr Point_m kWaypoint{6.0, 6.0};
constexpr double kHeading_rad = -0.25, kStep_s = 0.1, kTime_s = 30.0;

struct Sample {
  double t_s, x_m, y_m, theta_rad;
};
struct Path {
  std::vector<Sample> samples;
  double arrived_s = -1;   // < 0: never
};

// The previous rule's step (maneuver, beta, servos) from the pose it reads.
struct OldController {
  int maneuver = 1;
  bool idle = true;
  double servo_left = 0, servo_right = 0;
};

void old_controller_step(OldController& c, const BodyState& pose, bool accept) {
  const RobotParams rp;
  const auto p = controller_params(rp);
  if (c.idle) {
    if (accept) c = OldController{1, false, 0, 0};
    else c.servo_left = c.servo_right = 0;
    return;
  }
  const DeltaT<C> d{kWaypoint[0] - pose.x_m, kWaypoint[1] - pose.y_m};
  if (arrived_rule<C>(d, p.tolerance_m)) {
    c = OldController{1, true, 0, 0};
    return;
  }
  double beta;
  if (c.maneuver == 1) {
    beta = bearing_error_rule<C>(atan2_fix_rule<C>(d, p.tolerance_m), pose.theta_rad);   // re-read every step
    if (std::fabs(beta) < p.orient_tolerance_rad) c.maneuver = 2;
  } else {
    beta = bearing_error_rule<C>(d, pose.theta_rad);
    if (std::fabs(beta) > p.reorient_rad) c.maneuver = 1;
  }
  const double rho = std::sqrt(d.dx * d.dx + d.dy * d.dy);
  const double v = c.maneuver == 2 ? rho * p.k_v * (rho * rho * std::cos(beta) + beta * std::sin(beta)) : 0.0;
  const ServoPairT<C> mix = servo_mix_rule<C>(p, v, -p.k_beta * beta);
  c.servo_left = saturate_servo_rule<C>(mix.left);
  c.servo_right = saturate_servo_rule<C>(mix.right);
}

RobotConfig intocps_config() {
  Scenario s = default_scenario();
  s.params.step_size = kStep_s;
  s.body.kind = BodyKind::intocps;
  s.body.intocps.initial_position[2] = kHeading_rad;
  return make_robot_config(s);
}

Path run_before() {
  const RobotConfig c = intocps_config();
  BodyMemory body = initial_body(c, kStart);
  OldController ctrl;
  Path path;
  double t = 0;
  for (int k = 0; t < kTime_s; ++k) {
    old_controller_step(ctrl, body.pose, k == 1);
    body_advance(c, body, ctrl.servo_left, ctrl.servo_right, t);
    t = t + kStep_s;
    path.samples.push_back({t, body.pose.x_m, body.pose.y_m, body.pose.theta_rad});
    if (k > 1 && ctrl.idle && path.arrived_s < 0) path.arrived_s = t;
  }
  return path;
}

Path run_after() {
  const RobotConfig c = intocps_config();
  BodyMemory body = initial_body(c, kStart);
  ControllerState ctrl = initial_controller_of(c);
  ctrl.maneuver = 1;
  ctrl.on_destination_output = 1;
  Path path;
  double t = 0;
  for (int k = 0; t < kTime_s; ++k) {
    robot_step(c, ctrl, body, kWaypoint, k == 1 ? 1 : 0, t);
    t = t + kStep_s;
    path.samples.push_back({t, body.pose.x_m, body.pose.y_m, body.pose.theta_rad});
    if (k > 1 && ctrl.on_destination_output == 1 && path.arrived_s < 0) path.arrived_s = t;
  }
  return path;
}

// One panel: the reported point's path in a 0.2 m window around the waypoint (left) and the
// heading over time (right), at (x0, y0) in the picture.
std::string panel(const Path& p, const std::string& title, double y0) {
  constexpr double kMap = 240, kHalf_m = 0.1, kPlotW = 360;
  const double x0 = 20;
  const auto mx = [&](double x) { return x0 + (x - (kWaypoint[0] - kHalf_m)) / (2 * kHalf_m) * kMap; };
  const auto my = [&](double y) { return y0 + kMap - (y - (kWaypoint[1] - kHalf_m)) / (2 * kHalf_m) * kMap; };
  std::string out;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "<text x='%g' y='%g' font-size='15' font-weight='bold'>%s</text>\n"
                "<rect x='%g' y='%g' width='%g' height='%g' fill='#f7f7f7' stroke='#999'/>\n",
                x0, y0 - 10, title.c_str(), x0, y0, kMap, kMap);
  out += buf;
  // The arrival region |dx| + |dy| < tolerance, and the waypoint.
  const double tol = RobotParams{}.tolerance_m;
  std::snprintf(buf, sizeof buf,
                "<polygon points='%g,%g %g,%g %g,%g %g,%g' fill='#d8f0d8' stroke='#4a4'/>\n"
                "<circle cx='%g' cy='%g' r='3' fill='#2a2'/>\n",
                mx(kWaypoint[0] - tol), my(kWaypoint[1]), mx(kWaypoint[0]), my(kWaypoint[1] + tol), mx(kWaypoint[0] + tol),
                my(kWaypoint[1]), mx(kWaypoint[0]), my(kWaypoint[1] - tol), mx(kWaypoint[0]), my(kWaypoint[1]));
  out += buf;
  out += "<polyline fill='none' stroke='#c33' stroke-width='1.2' points='";
  out += std::to_string(mx(kStart[0])) + "," + std::to_string(my(kStart[1]));
  for (const Sample& s : p.samples) out += " " + std::to_string(mx(s.x_m)) + "," + std::to_string(my(s.y_m));
  out += "'/>\n";
  std::snprintf(buf, sizeof buf, "<circle cx='%g' cy='%g' r='3' fill='#33c'/>\n", mx(kStart[0]), my(kStart[1]));
  out += buf;
  // Heading over time.
  const double px = x0 + kMap + 40, pw = kPlotW;
  double lo = 1e9, hi = -1e9;
  for (const Sample& s : p.samples) lo = std::fmin(lo, s.theta_rad), hi = std::fmax(hi, s.theta_rad);
  lo -= 0.1, hi += 0.1;
  const auto tx = [&](double t) { return px + t / kTime_s * pw; };
  const auto ty = [&](double th) { return y0 + kMap - (th - lo) / (hi - lo) * kMap; };
  std::snprintf(buf, sizeof buf,
                "<rect x='%g' y='%g' width='%g' height='%g' fill='none' stroke='#999'/>\n"
                "<text x='%g' y='%g' font-size='11'>heading (rad), %.2f to %.2f, over %g s</text>\n",
                px, y0, pw, kMap, px + 4, y0 + 14, lo, hi, kTime_s);
  out += buf;
  out += "<polyline fill='none' stroke='#333' stroke-width='1' points='";
  for (const Sample& s : p.samples) out += std::to_string(tx(s.t_s)) + "," + std::to_string(ty(s.theta_rad)) + " ";
  out += "'/>\n";
  if (p.arrived_s >= 0) {
    std::snprintf(buf, sizeof buf,
                  "<line x1='%g' y1='%g' x2='%g' y2='%g' stroke='#2a2' stroke-dasharray='4 3'/>\n"
                  "<text x='%g' y='%g' font-size='12' fill='#2a2'>arrived at %.1f s</text>\n",
                  tx(p.arrived_s), y0, tx(p.arrived_s), y0 + kMap, tx(p.arrived_s) + 4, y0 + kMap - 6, p.arrived_s);
  } else {
    std::snprintf(buf, sizeof buf, "<text x='%g' y='%g' font-size='12' fill='#c33'>never arrives (%g s shown)</text>\n",
                  px + 4, y0 + kMap - 6, kTime_s);
  }
  out += buf;
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: minimal_stall_picture OUT.svg\n");
    return 2;
  }
  const Path before = run_before(), after = run_after();
  std::string svg =
      "<svg xmlns='http://www.w3.org/2000/svg' width='680' height='640' font-family='sans-serif'>\n"
      "<rect width='100%' height='100%' fill='white'/>\n"
      "<text x='20' y='22' font-size='13'>Minimal stall case on the 20-sim body: start (5.95, 5.937), heading -0.25, "
      "waypoint (6, 6), 0.1 s steps.</text>\n"
      "<text x='20' y='40' font-size='12' fill='#555'>Left: the reported point's path (0.2 m window; green: "
      "|dx| + |dy| &lt; 0.05). Right: the heading.</text>\n";
  svg += panel(before, "before: bearing re-read from the pose every orienting step", 80);
  svg += panel(after, "after: the heading to turn to latched (swarmcheck today)", 370);
  svg += "</svg>\n";
  std::FILE* f = std::fopen(argv[1], "w");
  if (f == nullptr || std::fputs(svg.c_str(), f) < 0 || std::fclose(f) != 0) {
    std::fprintf(stderr, "minimal_stall_picture: cannot write %s\n", argv[1]);
    return 2;
  }
  std::printf("%s: before %s, after %s\n", argv[1], before.arrived_s < 0 ? "never arrives" : "arrives",
              after.arrived_s < 0 ? "never arrives" : "arrives");
  return 0;
}
