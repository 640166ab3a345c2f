// The Controller and Body components, and the servo saturation.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <numbers>

#include "spec/exploration/body.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/controller_thesis.hpp"
#include "spec/exploration/handshake.hpp"

using namespace swarmcheck::exploration;
namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededExplorationControllerBodyTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kPi = std::numbers::pi;

// Any double, with the special values (NaN, infinities, signed zeros, extremes) well represented.
rc::Gen<double> any_double() {
  return rc::gen::oneOf(
      rc::gen::map(rc::gen::arbitrary<uint64_t>(), [](uint64_t b) { return std::bit_cast<double>(b); }),
      rc::gen::element(kNaN, kInf, -kInf, 0.0, -0.0, 1.0, -1.0, 1e308, -1e308, 5e-324),
      rc::gen::map(rc::gen::inRange(-4000, 4000), [](int k) { return k / 1000.0; }));
}
}  // namespace

TEST(Servo, SaturationMapsNaNToZeroAndClampsInfinities) {
  EXPECT_EQ(saturate_servo(kNaN), 0.0);
  EXPECT_EQ(saturate_servo(kInf), 1.0);
  EXPECT_EQ(saturate_servo(-kInf), -1.0);
  EXPECT_EQ(saturate_servo(0.25), 0.25);
  EXPECT_EQ(saturate_servo(-3.0), -1.0);
}

TEST(Servo, TheThesisClampLetsNaNThrough) {
  EXPECT_TRUE(std::isnan(thesis_clamp(kNaN)));
  EXPECT_EQ(thesis_clamp(2.0), 1.0);
}

RC_GTEST_PROP(Servo, SaturatedOutputIsInUnitRangeForEveryDouble, ()) {
  const double u = *any_double();
  const double s = saturate_servo(u);
  RC_ASSERT(s >= -1.0);
  RC_ASSERT(s <= 1.0);
}

RC_GTEST_PROP(Servo, ControllerServosAreInUnitRangeForEveryDoubleInput, ()) {
  ControllerState s = initial_controller();
  s.on_destination_output = 0;
  s.maneuver = *rc::gen::element(1, 2);
  s.target_theta_rad = *any_double();
  const ControllerInputs in{BodyState{*any_double(), *any_double(), *any_double()},
                            Point_m{*any_double(), *any_double()}, 0, *rc::gen::element(0.05, 0.1, 0.5, 1e-300, 1e300)};
  const ControllerState n = controller_step(RobotParams{}, s, in);
  RC_ASSERT(n.servo_left >= -1.0);
  RC_ASSERT(n.servo_left <= 1.0);
  RC_ASSERT(n.servo_right >= -1.0);
  RC_ASSERT(n.servo_right <= 1.0);
}

TEST(Angle, WrapIsInHalfOpenIntervalMinusPiToPi) {
  EXPECT_EQ(wrap_angle(kPi), kPi);
  EXPECT_EQ(wrap_angle(-kPi), kPi);
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-15);
  EXPECT_EQ(wrap_angle(0.5), 0.5);
}

TEST(Controller, IdleControllerAcceptsANewWaypointByLoweringItsOutput) {
  const ControllerState idle = initial_controller();
  const ControllerInputs in{BodyState{0.5, 0.5, 0}, Point_m{1.5, 0.5}, 1, 0.1};
  const ControllerState n = controller_step(RobotParams{}, idle, in);
  EXPECT_EQ(n.on_destination_output, 0);
  EXPECT_EQ(n.maneuver, 1);
  EXPECT_EQ(n.servo_left, 0.0);
  // It chose the heading to turn to: the waypoint is +x, and theta = -pi/2 faces +x.
  EXPECT_DOUBLE_EQ(n.target_theta_rad, -kPi / 2);
  // Without the Environment's signal it stays idle.
  EXPECT_EQ(controller_step(RobotParams{}, idle, {in.pose, in.waypoint, 0, 0.1}).on_destination_output, 1);
}

TEST(Controller, ArrivalRaisesTheOutputAndStops) {
  ControllerState moving = initial_controller();
  moving.on_destination_output = 0;
  moving.maneuver = 2;
  const ControllerInputs in{BodyState{1.49, 0.51, 0}, Point_m{1.5, 0.5}, 0, 0.1};
  const ControllerState n = controller_step(RobotParams{}, moving, in);
  EXPECT_EQ(n.on_destination_output, 1);
  EXPECT_EQ(n.maneuver, 1);
  EXPECT_EQ(n.servo_right, 0.0);
}

TEST(Controller, OrientingTurnsToTheHeadingChosenWhenItBeganWhereverThePoseReads) {
  // The stall on the 20-sim body: the reported point, 1.85 cm ahead of the axle, circles the axle
  // as the robot turns in place; a target recomputed from it flipped between two bearings.
  ControllerState s = initial_controller();
  s.on_destination_output = 0;
  s.target_theta_rad = 0.3;
  for (const BodyState pose : {BodyState{5.95, 5.937, -0.25}, BodyState{5.9475, 5.9372, -0.25}, BodyState{9, 9, -0.25}}) {
    const ControllerState n = controller_step(RobotParams{}, s, {pose, {6.0, 6.0}, 0, 0.1});
    EXPECT_EQ(n.beta_rad, 0.3 - -0.25);
    EXPECT_EQ(n.target_theta_rad, 0.3);
    EXPECT_EQ(n.maneuver, 1);
  }
}

TEST(Controller, DrivingTooFarOffTheBearingTurnsAgainTowardsATargetChosenThen) {
  ControllerState s = initial_controller();
  s.on_destination_output = 0;
  s.maneuver = 2;
  // The waypoint is straight behind (-y) a robot facing +y (theta 0): beta = pi > reorient.
  const ControllerState n = controller_step(RobotParams{}, s, {BodyState{1.5, 1.5, 0.0}, {1.5, 0.5}, 0, 0.1});
  EXPECT_EQ(n.maneuver, 1);
  EXPECT_DOUBLE_EQ(std::fabs(n.target_theta_rad), kPi);
  EXPECT_EQ(n.beta_rad, n.target_theta_rad - 0.0);
}

TEST(Controller, TheTurnGainIsCappedSoThatTheDelayedLoopGainIsAQuarter) {
  // K k dt <= 1/4: at 0.5 s the turn command is 0.25 / (5.18 * 0.5) of beta, not k_beta = 1.
  ControllerState s = initial_controller();
  s.on_destination_output = 0;
  s.target_theta_rad = 0.1;   // a small turn, unsaturated
  const RobotParams rp;
  for (const double dt : {0.05, 0.1, 0.5}) {
    const ControllerState n = controller_step(rp, s, {BodyState{1, 1, 0}, {1, 3}, 0, dt});
    const double k = std::min(rp.k_beta, rp.loop_gain / (rp.motor_gain_rad_per_s * dt));
    const double w = -k * 0.1;
    EXPECT_EQ(n.servo_left, (2 * rp.half_axle_m / (2 * rp.wheel_radius_m)) * w) << dt;
  }
}

TEST(Body, FullForwardDrivesAlongMinusSinCos) {
  const RobotParams rp;
  const double rk = rp.wheel_radius_m * rp.motor_gain_rad_per_s;
  const BodyState n = body_step(rp, BodyState{0, 0, 0}, 1.0, -1.0, 0.1);
  EXPECT_EQ(n.theta_rad, 0.0);
  EXPECT_EQ(n.x_m, 0.0);
  EXPECT_DOUBLE_EQ(n.y_m, rk * 0.1);
  const BodyState m = body_step(rp, BodyState{0, 0, kPi / 2}, 1.0, -1.0, 1.0);   // faces -x
  EXPECT_DOUBLE_EQ(m.x_m, -rk);
  EXPECT_NEAR(m.y_m, 0.0, 1e-16);
}

TEST(Body, EqualServosTurnInPlaceAndExactIntegrationClosesACircle) {
  const RobotParams rp;
  const BodyState spin = body_step(rp, BodyState{1, 2, 0}, 1.0, 1.0, 0.1);
  EXPECT_EQ(spin.x_m, 1.0);
  EXPECT_EQ(spin.y_m, 2.0);
  EXPECT_LT(spin.theta_rad, 0.0);   // omega = -r K (uL + uR) / 2a
  // One wheel only: the body drives an arc; a whole turn brings it back.
  const double rk = rp.wheel_radius_m * rp.motor_gain_rad_per_s;
  const double omega = rk * 1.0 / (2 * rp.half_axle_m);
  BodyState b{0, 0, 0};
  b = body_step(rp, b, 0.0, -1.0, 2 * kPi / omega);
  EXPECT_NEAR(b.x_m, 0.0, 1e-12);
  EXPECT_NEAR(b.y_m, 0.0, 1e-12);
}

// Closed loop: controller + body under the Jacobi exchange, from any start pose to any
// waypoint within 4 m, arrives within the tolerance in a bounded number of steps.
RC_GTEST_PROP(ClosedLoop, ControllerBringsBodyWithinToleranceOfAnyWaypointInBoundedSteps, ()) {
  const RobotParams rp;
  auto coord = rc::gen::map(rc::gen::inRange(-4000, 4001), [](int k) { return k / 1000.0; });
  BodyState body{*coord, *coord, *rc::gen::map(rc::gen::inRange(-31416, 31417), [](int k) { return k / 1e4; })};
  const Point_m wp{body.x_m + *coord, body.y_m + *coord};
  ControllerState ctrl = initial_controller();
  ctrl.on_destination_output = 0;   // a waypoint was just accepted
  const int64_t steps_max = 4000;   // 400 s at dt = 0.1 s
  BodyState seen = body;            // the pose the controller read when it raised its output
  for (int64_t k = 0; k < steps_max && ctrl.on_destination_output == 0; ++k) {
    const ControllerState before = ctrl;
    seen = body;
    ctrl = controller_step(rp, before, {body, wp, 0, 0.1});
    body = body_step(rp, body, before.servo_left, before.servo_right, 0.1);
  }
  RC_ASSERT(ctrl.on_destination_output == 1);
  RC_ASSERT(std::fabs(wp[0] - seen.x_m) + std::fabs(wp[1] - seen.y_m) < rp.tolerance_m);
}

TEST(Handshake, EnvironmentTableOfTheThesis) {
  const HandshakeState init = initial_handshake();
  EXPECT_EQ(init.flag, 1);
  EXPECT_EQ(init.on_destination_output, 0);
  const HandshakeStep a = environment_handshake(init, true);
  EXPECT_TRUE(a.plan);
  EXPECT_EQ(a.next.flag, 0);
  EXPECT_EQ(a.next.on_destination_output, 1);
  const HandshakeStep b = environment_handshake(a.next, true);
  EXPECT_FALSE(b.plan);
  EXPECT_EQ(b.next.flag, 1);
  EXPECT_EQ(b.next.on_destination_output, 0);
  const HandshakeStep c = environment_handshake(a.next, false);
  EXPECT_FALSE(c.plan);
  EXPECT_EQ(c.next.flag, 0);
  EXPECT_EQ(c.next.on_destination_output, 1);
}

// The UController FMU's rho, v and w (thesis_controller_locals) are the ones its step used: the
// servos they give, clamped as the thesis clamps, are the step's, bit for bit; and an idle step
// or one the Environment's flag ends computes none.
RC_GTEST_PROP(ThesisControllerLocals, TheirVAndWGiveTheStepsServosBitForBit, ()) {
  using C = swarmcheck::num::Concrete;
  const ThesisControllerParams p;
  const auto coord = rc::gen::map(rc::gen::inRange(-3000, 3000), [](int k) { return k / 1000.0; });
  const ControllerState s{*rc::gen::element(1, 2), *rc::gen::element(0, 0, 0, 1), 0.0, 0.0, 0.0, 0.0};
  const ControllerInputs in{{*coord, *coord, *rc::gen::map(rc::gen::inRange(-7000, 7000), [](int k) { return k / 1000.0; })},
                            {*coord, *coord}, *rc::gen::element(0, 0, 0, 1), 0.1};
  const ControllerState next = thesis_controller_step(p, s, in);
  const ControllerLocals l = thesis_controller_locals(p, s, in);
  if (in.on_destination_input == 1 || s.on_destination_output == 1) {
    RC_ASSERT(l.rho_m == 0.0 && l.v == 0.0 && l.w == 0.0);
    return;
  }
  const double r = p.wheel_radius_m, wd = p.wheel_distance_m;
  const double left = thesis_clamp_rule<C>((1.0 / r) * l.v + (wd / (2.0 * r)) * l.w);
  const double right = thesis_clamp_rule<C>(-((1.0 / r) * l.v - (wd / (2.0 * r)) * l.w));
  RC_ASSERT(std::bit_cast<uint64_t>(left) == std::bit_cast<uint64_t>(next.servo_left));
  RC_ASSERT(std::bit_cast<uint64_t>(right) == std::bit_cast<uint64_t>(next.servo_right));
  RC_ASSERT(l.w == -p.k_beta * next.beta_rad);
}
