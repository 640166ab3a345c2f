// swarmcheck::Exploration: the optimised master. Robot state is structure-of-arrays; in cosim
// mode every robot's controller and body step from the previous outputs (Jacobi), which makes
// them independent of each other and of the Environment's step within a master step.
#include "swarmcheck/exploration.hpp"

#include <tbb/parallel_for.h>

#include <cmath>

#include "impl/exploration/environment.hpp"
#include "impl/exploration/intocps_bodies.hpp"
#include "spec/exploration/body.hpp"
#include "spec/exploration/master.hpp"
#include "spec/exploration/robot.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::exploration {

namespace impl = swarmcheck::impl::exploration;

// The master's stages (spec/exploration/master.hpp) over the optimised components.
struct Exploration::State {
  State(const Scenario& s, ExplorationOptions o, RobotParams rp)
      : options(o), robot(make_robot_config(s, rp)), env(s, o) {}
  ExplorationOptions options;
  RobotConfig robot;
  impl::Environment env;
  double clock_s = 0.0;   // the master's time, by repeated addition of the step (spec/exploration/robot.hpp)
  std::vector<ControllerState> ctrl;
  std::vector<BodyState> body;    // each robot's pose, as its controller reads it
  std::vector<Heading> heading;   // heading_of(body[r].theta_rad), kept from the step that made it (kinematic)
  impl::IntocpsBodies intocps;    // the intocps bodies (empty with the kinematic body)
  std::vector<double> servo_left, servo_right;   // the servos a step's intocps bodies hold

  std::span<const ControllerState> controllers() const { return ctrl; }
  int32_t environment_output() const { return env.state().handshake.on_destination_output; }
  void robots_step(int32_t env_output);
  void environment_step(bool all_arrived) { env.step(all_arrived); }
  void place_bodies_on_waypoints();
  bool parallel_robots() const {
    return env.threads() > 1 && static_cast<int64_t>(body.size()) >= options.parallel_min_bodies;
  }
  // Each robot's controller (and kinematic body) from the previous outputs, in parallel when there are many.
  template <class Step>
  void for_each_robot(const Step& step) {
    const std::size_t n = body.size();
    if (parallel_robots())
      env.arena().execute([&] { tbb::parallel_for(std::size_t{0}, n, [&](std::size_t r) { step(r); }); });
    else
      for (std::size_t r = 0; r < n; ++r) step(r);
  }
  void step_kinematic_robot(std::size_t r, int32_t env_output, const Point_m& waypoint);
};

// One robot's controller and kinematic body from the previous outputs. A body whose servos are
// both 0 stays exactly where it is (the spec's straight-line branch adds +-0), so the step is
// skipped; -0.0 coordinates, where adding +0 would change the bits, take the full formula.
void Exploration::State::step_kinematic_robot(std::size_t r, int32_t env_output, const Point_m& waypoint) {
  const ControllerState before = ctrl[r];
  const BodyState pose = body[r];
  ctrl[r] = controller_step(robot, before, ControllerInputs{pose, waypoint, env_output, robot.step_s});
  if (body_stays(pose, before.servo_left, before.servo_right)) return;
  const BodyStep next = body_step_with_heading(robot.robot, pose, heading[r], before.servo_left, before.servo_right,
                                               robot.step_s);
  body[r] = next.state;
  heading[r] = next.heading;
}

void Exploration::State::robots_step(int32_t env_output) {
  const auto& robots = env.state().robots;   // still the previous step's waypoints
  switch (robot.body->dynamics) {
    case BodyDynamics::steady_state_unicycle:
      for_each_robot([&](std::size_t r) { step_kinematic_robot(r, env_output, robots[r].waypoint); });
      break;
    case BodyDynamics::twenty_sim_rk4:
      // The servos the bodies hold are the controllers' previous outputs: kept before the controllers step.
      for (std::size_t r = 0; r < ctrl.size(); ++r) {
        servo_left[r] = ctrl[r].servo_left;
        servo_right[r] = ctrl[r].servo_right;
      }
      for_each_robot([&](std::size_t r) {
        ctrl[r] = controller_step(robot, ctrl[r], ControllerInputs{body[r], robots[r].waypoint, env_output, robot.step_s});
      });
      intocps.step(servo_left, servo_right, clock_s, robot.step_s, env.arena(), parallel_robots());
      for (std::size_t r = 0; r < body.size(); ++r) body[r] = intocps.pose(r);
      break;
  }
  clock_s = clock_s + robot.step_s;
}

void Exploration::State::place_bodies_on_waypoints() {
  const auto& robots = env.state().robots;
  for (std::size_t r = 0; r < body.size(); ++r) {
    body[r].x_m = robots[r].waypoint[0];
    body[r].y_m = robots[r].waypoint[1];
  }
}

std::uint64_t Exploration::estimated_bytes(const Scenario& s) {
  // Per robot: pose, environment record, planning scratch and candidates (about 256 bytes).
  return swarmcheck::impl::exploration::LazyGrid::bytes_for(s.map_size) + std::uint64_t{256} * s.robots.size();
}

Exploration::Exploration(const Scenario& s, ExplorationOptions options, RobotParams robot) {
  validate(s);
  init(s, options, robot);
}

Exploration::Exploration(const ValidScenario& s, ExplorationOptions options, RobotParams robot) {
  init(s.get(), options, robot);
}

void Exploration::init(const Scenario& s, ExplorationOptions options, RobotParams robot) {
  state_ = std::make_unique<State>(s, options, robot);
  State& st = *state_;
  const std::size_t n = s.robots.size();
  st.ctrl.assign(n, initial_controller_of(st.robot));
  st.body.reserve(n);
  for (const Point_m& p : s.robots) st.body.push_back(initial_body(st.robot, p).pose);
  st.heading.reserve(n);
  for (const BodyState& b : st.body) st.heading.push_back(heading_of(b.theta_rad));
  if (st.robot.body->dynamics == BodyDynamics::twenty_sim_rk4) {
    st.intocps = impl::IntocpsBodies(st.robot.intocps, s.robots);
    st.servo_left.assign(n, 0.0);
    st.servo_right.assign(n, 0.0);
  }
}

Exploration::~Exploration() = default;
Exploration::Exploration(Exploration&&) noexcept = default;
Exploration& Exploration::operator=(Exploration&&) noexcept = default;

void Exploration::step() { master_step(state_->env.scenario().mode, *state_); }

bool Exploration::done() const {
  const EnvironmentState& e = state_->env.state();
  return e.progress.completion_step.has_value() || e.tick >= state_->env.scenario().max_steps;
}
int64_t Exploration::steps() const { return state_->env.state().tick; }
int64_t Exploration::planning_steps() const { return state_->env.state().planning_steps; }
int64_t Exploration::visited() const { return state_->env.state().progress.visited; }
int64_t Exploration::free_cells() const { return state_->env.state().progress.free_cells; }
double Exploration::eP() const { return state_->env.state().progress.eP; }
double Exploration::sTime() const { return state_->env.state().progress.sTime; }
std::optional<int64_t> Exploration::completion_step() const { return state_->env.state().progress.completion_step; }
Cell Exploration::cell(CellIndex c) const { return state_->env.cell(c); }
const Scenario& Exploration::scenario() const { return state_->env.scenario(); }
std::span<const BodyState> Exploration::bodies() const { return state_->body; }
std::span<const EnvRobot> Exploration::robots() const { return state_->env.state().robots; }

StepRecord Exploration::record() const {
  const State& st = *state_;
  return make_step_record(st.env.state(), st.env.digest(), st.ctrl, st.body, st.intocps.states());
}

}  // namespace swarmcheck::exploration
