#pragma once
// @component Body `intocps`: thesis A's 20-sim Body_Block (R2G2P_Body_Only_marcel2, exported by
// 20-sim 4.6 as Body_Block1..4.fmu), as its binary computes it. ../shared/thesis-body.md states
// the model; spec/SPEC.md section 9 summarises it.
//   parameters: IntocpsBodyParams (the FMU's names and value references: kIntocpsBodyParameters)
//   inputs:     servo_left_input u_L, servo_right_input u_R (not clamped; the right motor is mirrored)
//   state:      16 continuous states (energies, momenta, displacement, heading change, motor
//               angles, flux linkages, PI integrals), the rates of the last rate evaluation F, the
//               contact velocities W and positions of the last output evaluation G, battery memory,
//               the solver clock
//   outputs:    robot_x, robot_y (the point P, `axle_offset` ahead of the axle, as it was one
//               solver step (1 ms) before), robot_theta, wheel rotations, encoder counts,
//               total_energy_used: all known at communication points only (no feedthrough)
//
// The discrete scheme (thesis-body.md section 6) is what must match bit for bit: classical RK4 at
// h = 1 ms; F reads the contact velocities of the LAST G (a one-step lag on the wheel/body coupling);
// a communication step from t over H runs RK4 steps while the solver clock, accumulated by repeated
// addition of h, is below t + H (so 99, 100 or 101 steps for 0.1 s). Each operation below is in the
// order and association the binary uses; do not "simplify" one (a-b)-c into a-(b+c).
#include <array>
#include <cstdint>
#include <span>
#include <string_view>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

// The Body_Block's FMI parameters (SI units), with its defaults. Left and right servos have their
// own (equal) parameters.
struct IntocpsServoParams {
  double friction_r = 0.0126;          // f: motor viscous friction, N m s/rad
  double inductance_i = 0.071;         // L: winding inductance, H
  double kp = 1.0;                     // k_p: PI gain, V s/rad
  double tau_i = 0.1;                  // tau_I: PI integral time, s
  double motor_constant_r = 0.796;     // k_m: torque / back-EMF constant, N m/A
  double pwm_to_speed_k = 5.18;        // K_s: wheel speed per unit servo input, rad/s
  double resistance_r = 8.2;           // R_a: winding resistance, Ohm
  double voltage_maximum = 20.0;       // V_max: PI output clamp, V
  double voltage_minimum = -20.0;      // V_min
  bool operator==(const IntocpsServoParams&) const = default;
};

struct IntocpsBodyParams {
  double battery_initial_energy = 2500.0;       // E0, J
  double individual_sensor_power = 0.5;         // P_s, W per line-follower sensor
  double controller_power = 7.0;                // P_c, W
  double battery_power_on = 1.0;                // Battery.powerOn: voltage factor with energy left
  double battery_power_off = 0.0;               // Battery.powerOff: without
  double axle_offset = 0.0185;                  // a: P ahead of the axle, m
  double axle_half_width = 0.049;               // b: half track, m
  double robot_inertia_without_battery = 6.6e-4;   // J_r, kg m^2
  double battery_mass = 0.415;                  // m_b, kg
  double battery_length = 0.12;                 // l_b, m
  double battery_width = 0.03;                  // w_b, m
  double battery_cog_offset = 0.05;             // o_b, m
  double robot_mass_without_battery = 0.414;    // m_r, kg
  std::array<double, 3> initial_position{0.138, -0.08, 0.0};   // x0, y0 (m), theta0 (rad) of P
  double mu = 1332.0;                           // viscous ground-friction coefficient, N s/m^2
  double blade_position = 0.08;                 // body.R.bladePosition, m
  double encoder_resolution = 44.0;             // N_enc, counts per revolution
  double encoder_left_lsb = 1.0;                // encoder_left.Quantisize.lsb, counts
  double encoder_right_lsb = 1.0;               // encoder_right.Quantisize.lsb
  double num_sensors = 2.0;                     // n_s: 1..5 sensors draw power; any other value none
  double wheel_radius = 0.03325;                // r, m
  double wheel_thickness = 0.0045;              // m (the model does not use it)
  double wheel_material_density = 1180.0;       // kg/m^3 (the model does not use it)
  IntocpsServoParams servo_left;
  IntocpsServoParams servo_right;
  double wheel_left_lateral_damping = 500.0;    // wheel_left.R.r: d, N s/m
  double wheel_right_lateral_damping = 500.0;   // wheel_right.R2.r
  bool operator==(const IntocpsBodyParams&) const = default;
};

// A scenario's intocps body: the FMU's defaults, but battery_initial_energy 1e21 J as thesis A's
// multi-model sets it (the default 2500 J lasts about 300 s; the thesis preset runs the default map for 2664 s).
IntocpsBodyParams scenario_intocps_params();

// One FMI parameter: its name in the FMU and in scenario files, its value reference, its member.
struct IntocpsBodyParameter {
  std::string_view name;
  uint32_t value_reference;
  double IntocpsBodyParams::*member;          // null for an element of initial_position or a servo's
  int32_t initial_position_index;             // 0..2, or -1
  int32_t servo;                              // 0 left, 1 right, -1 neither
  double IntocpsServoParams::*servo_member;   // with servo >= 0
};
std::span<const IntocpsBodyParameter> intocps_body_parameters();
// The parameter named `name`, or null.
const IntocpsBodyParameter* find_intocps_body_parameter(std::string_view name);
double& intocps_parameter_ref(IntocpsBodyParams& p, const IntocpsBodyParameter& d);
double intocps_parameter_value(const IntocpsBodyParams& p, const IntocpsBodyParameter& d);

// What the binary derives from the parameters: constant for a run.
struct IntocpsBodyModel {
  IntocpsBodyParams p;
  double inv_mass;           // 1 / (m_r + m_b)
  double inertia;            // J = J_r + ((((m_b/12)(l_b l_b))(w_b w_b)) + m_b (o_b o_b))
  double ground_friction;    // c = ((m_r a)/l_blade) mu + ((m_b o_b)/l_blade) mu
  double sensor_power;       // n_s' P_s
  double pi_integral_gain_left, pi_integral_gain_right;   // k_p / tau_I
};
IntocpsBodyModel intocps_body_model(const IntocpsBodyParams& p);

// The 16 states, in the binary's order (thesis-body.md section 3).
enum IntocpsState : int {
  kControllerEnergy = 0,   // E_c, J
  kSensorEnergy = 1,       // E_s, J
  kAngularMomentum = 2,    // h = J omega
  kMomentumX = 3,          // p, world frame
  kMomentumY = 4,
  kDisplacementX = 5,      // xi: P's displacement from (x0, y0), world frame
  kDisplacementY = 6,
  kHeadingChange = 7,      // phi: theta = theta0 + phi
  kWheelLeftAngle = 8,     // alpha_L
  kWheelRightAngle = 9,    // alpha_R
  kMotorLeftEnergy = 10,   // E_L
  kFluxLeft = 11,          // lambda_L = L i_L
  kPiIntegralLeft = 12,    // z_L
  kMotorRightEnergy = 13,  // E_R
  kFluxRight = 14,         // lambda_R
  kPiIntegralRight = 15,   // z_R
};
inline constexpr int kIntocpsStates = 16;

// The FMU's outputs as of the last G.
struct IntocpsBodyOutputs {
  BOOST_HANA_DEFINE_STRUCT(IntocpsBodyOutputs,
      (double, robot_x),                 // m: P one solver step ago
      (double, robot_y),
      (double, robot_theta),             // rad, unwrapped
      (double, wheel_left_rotation),     // rad
      (double, wheel_right_rotation),
      (double, encoder_left_output),     // counts
      (double, encoder_right_output),
      (double, total_energy_used));      // J
};

// The whole memory of one Body_Block: what a step reads and writes.
struct IntocpsBodyState {
  BOOST_HANA_DEFINE_STRUCT(IntocpsBodyState,
      (std::array<double, kIntocpsStates>, states),
      (std::array<double, kIntocpsStates>, rates),   // of the last F
      (std::array<double, 4>, contact),              // W: c_L (x, y), c_R (x, y), body frame, of the last G
      (std::array<double, 2>, position),             // POS: P from the last G
      (std::array<double, 2>, reported),             // D: POS as the last F copied it (robot_x, robot_y)
      (double, theta),                               // Theta: theta of the last F
      (double, battery_remaining),                   // J, of the last F (>= 0)
      (double, controller_energy_seen),              // E_c*: frozen once the battery is empty
      (double, sensor_energy_seen),                  // E_s*
      (double, solver_time_s),                       // t_s, by repeated addition of h
      (std::array<double, 2>, origin),               // initial_position[0..1]: this instance's x0, y0
      (IntocpsBodyOutputs, outputs));
};

inline constexpr double kIntocpsSolverStep_s = 0.001;   // h, fixed in the binary's code

// fmi2SetupExperiment(start): the binary resets every parameter to its default, zeroes the states,
// runs F and G once (with those defaults and zero inputs) and leaves W, POS, D as the process held
// them (zeros in a fresh process). The run's parameters, written after this call as FMI masters do,
// take effect from the next F and G: so right after initialisation robot_x and robot_y read 0 and
// robot_theta the default theta0 = 0, whatever initial_position says. x0 and y0 are per instance
// (`origin`, which G reads): the caller sets them after this call, as it writes the parameters;
// theta0 and the other parameters are the model's.
IntocpsBodyState intocps_body_setup(double start_time_s);
// Setup, then this instance's x0, y0: a body as an FMI master leaves it after initialisation.
IntocpsBodyState intocps_body_initialised(double start_time_s, double x0_m, double y0_m);

// One RK4 step of h (t_s -> t_s + h) with inputs (u_L, u_R).
void intocps_body_rk4_step(const IntocpsBodyModel& m, IntocpsBodyState& s, double servo_left, double servo_right);

// The RK4 steps of fmi2DoStep(t, H): none when H = 0; else while t_s < t + H. Returns the number.
int32_t intocps_body_do_step(const IntocpsBodyModel& m, IntocpsBodyState& s, double servo_left, double servo_right,
                             double t_s, double h_s);
// The number of RK4 steps fmi2DoStep(t, H) runs from solver clock t_s, and the clock after them:
// the same for every robot stepped together, so a batched caller counts once.
struct IntocpsSolverSteps {
  int32_t count;
  double clock_after_s;
};
IntocpsSolverSteps intocps_solver_steps(double solver_time_s, double t_s, double h_s);

// Pure form: the state after fmi2DoStep(t, H) with these inputs.
IntocpsBodyState intocps_body_step(const IntocpsBodyModel& m, const IntocpsBodyState& s, double servo_left,
                                   double servo_right, double t_s, double h_s);

// Rot(theta)'s inverse as the binary forms it (LU with partial pivoting; a pivot swap when
// |A10| > |A00| strictly), and (0 + M00 v0) + M01 v1 per row: exposed for tests.
using Mat2 = std::array<std::array<double, 2>, 2>;
Mat2 intocps_lu_inverse(const Mat2& a);

}  // namespace swarmcheck::exploration
