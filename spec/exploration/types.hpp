#pragma once
// Value types of the exploration system (system A). Plain data, declared once with
// BOOST_HANA_DEFINE_STRUCT so that JSON I/O, field names and field-by-field diffs are derived.
//
// Like mjModel / mjData: `Scenario` is constant for a run, the *State types are what a step
// changes. Units are in the names where a quantity has one (_m metres, _rad radians, _s seconds).
#include <array>
#include <boost/hana.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "spec/exploration/body_intocps.hpp"
#include "spec/exploration/robot_kinds.hpp"
#include "spec/exploration/rule_set.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

using Point_m = std::array<double, 2>;      // [x, y] in metres
using CellIndex = std::array<int32_t, 2>;   // [i, j], 0-based; cell (i, j) covers
                                            // [i*s, (i+1)*s) x [j*s, (j+1)*s)

enum class Mode { abstract, cosim };

// The exploration algorithm's parameters, with the thesis's names.
struct Params {
  BOOST_HANA_DEFINE_STRUCT(Params,
      (int32_t, s_range),     // sensing and spraying range, cells (Chebyshev), >= 1
      (double, a1),           // deposit decay length, cells, > 0
      (double, a2),           // divisor of the uniform deposit term, > 0
      (double, epsilon),      // uniform deposit numerator, >= 0
      (double, max_ph),       // peak deposit, >= 0
      (double, ertu),         // evaporation rate, 1/s, >= 0
      (double, eta),          // heuristic factor (one scalar), > 0
      (double, phi),          // pheromone exponent
      (double, lambda),       // heuristic exponent
      (double, step_size));   // master step, s, > 0
};

// Which body every robot has, with the intocps body's parameters (read only when kind is
// intocps). Scenario files spell it "kinematic", "intocps" or {"kind": "intocps", "parameters":
// {FMU name: value}}; initial_position[0..1] of each robot is its entry in `robots`.
struct BodyChoice {
  BodyKind kind = BodyKind::kinematic;
  IntocpsBodyParams intocps = scenario_intocps_params();
  bool operator==(const BodyChoice&) const = default;
};

// A run's input: the scenario file's keys, exactly.
struct Scenario {
  BOOST_HANA_DEFINE_STRUCT(Scenario,
      (int32_t, map_size),                 // N: the map is N x N cells
      (double, cell_size),                 // metres per cell side
      (std::vector<Point_m>, robots),      // start positions, metres
      (std::vector<CellIndex>, obstacles), // obstacle cells
      (Params, params),
      (RuleSet, rule),
      (Mode, mode),
      (uint64_t, seed),                    // the one seed of the run (stochastic rule)
      (int64_t, max_steps),                // master steps at most
      (ControllerKind, controller),        // every robot's controller (cosim mode)
      (BodyChoice, body));                 // every robot's body (cosim mode)
};

// Robot hardware and controller gains: fixed constants of the spec (not scenario keys).
struct RobotParams {
  double wheel_radius_m = 0.03325;        // r, INTO-CPS Body_Block
  double motor_gain_rad_per_s = 5.18;     // K: wheel speed per unit servo command
  double half_axle_m = 0.049;             // a: half the distance between the wheels
  double k_v = 100.0;                     // linear gain of maneuver 2
  double k_beta = 1.0;                    // rotation gain
  double tolerance_m = 0.05;              // arrival: |dx| + |dy| < tolerance; atan2 deadband
  double orient_tolerance_rad = 0.01;     // maneuver 1 ends when |beta| < this
  double reorient_rad = 0.2;              // maneuver 2 falls back to 1 when |beta| > this
  // The turn and approach gains are capped so that K gain dt <= loop_gain: with the master's
  // one-step delay the error then follows e(k+2) = e(k+1) - loop_gain e(k), a double root 1/2 at
  // 1/4 (no overshoot, SPEC.md section 8), whatever the step.
  double loop_gain = 0.25;
};

// One cell of the grid. The pheromone is stored as the value written at `pheromone_tick`;
// under the decay evaporation its value at tick t is pheromone * F(t - pheromone_tick).
struct Cell {
  BOOST_HANA_DEFINE_STRUCT(Cell,
      (double, pheromone),
      (int64_t, pheromone_tick),
      (bool, visited),
      (bool, obstacle),
      (int32_t, occupant));   // index of the robot standing here, or -1
};

// The Environment's handshake state (thesis: `flag`, `onDestinationOutput`).
struct HandshakeState {
  BOOST_HANA_DEFINE_STRUCT(HandshakeState,
      (int32_t, flag),
      (int32_t, on_destination_output));
};

// Controller state and outputs (thesis Controller FMU).
struct ControllerState {
  BOOST_HANA_DEFINE_STRUCT(ControllerState,
      (int32_t, maneuver),                // 1 orient, 2 drive
      (int32_t, on_destination_output),   // 1: at its waypoint and idle
      (double, beta_rad),
      (double, servo_left),               // in [-1, 1]
      (double, servo_right),              // in [-1, 1]
      (double, target_theta_rad));        // the heading maneuver 1 turns to, chosen when it began
};

// Body state = its outputs (pose). Forward is (-sin theta, cos theta).
struct BodyState {
  BOOST_HANA_DEFINE_STRUCT(BodyState,
      (double, x_m),
      (double, y_m),
      (double, theta_rad));
};

// What the Environment knows of one robot.
struct EnvRobot {
  BOOST_HANA_DEFINE_STRUCT(EnvRobot,
      (CellIndex, cell),        // the cell the Environment moved it to
      (Point_m, waypoint));     // the waypoint it issued (xDesired, yDesired)
};

// The observable state after a step: one trace record; what impl and model must agree on.
struct RobotRecord {
  BOOST_HANA_DEFINE_STRUCT(RobotRecord,
      (CellIndex, cell),
      (Point_m, waypoint),
      (BodyState, body),                                  // the pose its controller reads
      (ControllerState, controller),
      (std::optional<IntocpsBodyState>, body_states));    // the intocps body's whole memory
};

struct StepRecord {
  BOOST_HANA_DEFINE_STRUCT(StepRecord,
      (int64_t, step),                 // master steps done
      (int64_t, planning_steps),       // steps in which the Environment chose new cells
      (HandshakeState, handshake),
      (int64_t, visited),
      (int64_t, free_cells),
      (double, eP),                    // exploration percentage
      (double, sTime),                 // s
      (uint64_t, pheromone_digest),    // FNV-1a over the bits of every cell's current value
      (std::vector<RobotRecord>, robots));
};

}  // namespace swarmcheck::exploration

namespace swarmcheck::json_io {
template <>
struct JsonCodec<exploration::BodyChoice> {
  static Json write(const exploration::BodyChoice& b);
  static void read(const Json& j, const std::string& path, exploration::BodyChoice& out);
};
template <>
struct OmitWhenDefault<exploration::BodyChoice> : std::true_type {};
template <>
struct OmitWhenDefault<std::optional<exploration::IntocpsBodyState>> : std::true_type {};

template <>
struct EnumNames<exploration::Mode> {
  static constexpr std::array<std::pair<exploration::Mode, std::string_view>, 2> names{{
      {exploration::Mode::abstract, "abstract"},
      {exploration::Mode::cosim, "cosim"},
  }};
};
}  // namespace swarmcheck::json_io
