// swarmcheck::Exploration: the optimised master. Robot state is structure-of-arrays; in cosim
// mode every robot's controller and body step from the previous outputs (Jacobi), which makes
// them independent of each other and of the Environment's step within a master step.
#include "swarmcheck/exploration.hpp"

#include <tbb/parallel_for.h>

#include <cmath>

#include "impl/exploration/body_kernel.hpp"
#include "impl/exploration/environment.hpp"
#include "spec/exploration/controller.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck {

using namespace exploration;

struct Exploration::State {
  State(const Scenario& s, ExplorationOptions o, RobotParams rp) : options(o), robot(rp), env(s, o) {}
  ExplorationOptions options;
  RobotParams robot;
  impl::Environment env;
  std::vector<ControllerState> ctrl;
  std::vector<BodyState> body;
  std::vector<impl::Heading> heading;   // cos and sin of body[r].theta_rad
  int64_t arrived = 0;   // controllers whose onDestinationOutput is 1

  void step_robot(std::size_t r, int32_t env_output, const Point_m& waypoint);
};

namespace {
bool negative_zero(double v) { return v == 0 && std::signbit(v); }
}  // namespace

// One robot's controller and body from the previous outputs. A body whose servos are both 0
// stays exactly where it is (the spec's straight-line branch adds +-0), so the trigonometry is
// skipped; -0.0 coordinates, where adding +0 would change the bits, take the full formula.
void Exploration::State::step_robot(std::size_t r, int32_t env_output, const Point_m& waypoint) {
  const ControllerState before = ctrl[r];
  const BodyState pose = body[r];
  ctrl[r] = controller_step(robot, before, ControllerInputs{pose, waypoint, env_output});
  const bool still = before.servo_left == 0 && before.servo_right == 0 && !negative_zero(pose.x_m) &&
                     !negative_zero(pose.y_m) && !negative_zero(pose.theta_rad);
  if (!still)
    impl::body_step_cached(robot, body[r], heading[r], before.servo_left, before.servo_right,
                           env.scenario().params.step_size);
}

Exploration::Exploration(const Scenario& s, ExplorationOptions options, RobotParams robot) {
  validate(s);
  state_ = std::make_unique<State>(s, options, robot);
  for (const Point_m& p : s.robots) {
    state_->ctrl.push_back(initial_controller());
    state_->body.push_back(BodyState{p[0], p[1], 0.0});
    state_->heading.push_back(impl::heading_of(0.0));
  }
  state_->arrived = static_cast<int64_t>(s.robots.size());
}

Exploration::~Exploration() = default;
Exploration::Exploration(Exploration&&) noexcept = default;
Exploration& Exploration::operator=(Exploration&&) noexcept = default;

void Exploration::step() {
  State& st = *state_;
  const std::size_t n = st.body.size();
  if (st.env.scenario().mode == Mode::abstract) {
    st.env.step(true);
    for (std::size_t r = 0; r < n; ++r) {
      st.body[r].x_m = st.env.waypoints()[r][0];
      st.body[r].y_m = st.env.waypoints()[r][1];
    }
    return;
  }
  const bool all_arrived = st.arrived == static_cast<int64_t>(n);
  const int32_t env_output = st.env.handshake().on_destination_output;
  const auto& waypoints = st.env.waypoints();   // still the previous step's outputs
  if (static_cast<int64_t>(n) >= st.options.parallel_min_bodies) {
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t r) { st.step_robot(r, env_output, waypoints[r]); });
  } else {
    for (std::size_t r = 0; r < n; ++r) st.step_robot(r, env_output, waypoints[r]);
  }
  st.env.step(all_arrived);
  int64_t arrived = 0;
  for (const ControllerState& c : st.ctrl) arrived += c.on_destination_output;
  st.arrived = arrived;
}

bool Exploration::done() const {
  return state_->env.completion_step().has_value() || state_->env.tick() >= state_->env.scenario().max_steps;
}
int64_t Exploration::steps() const { return state_->env.tick(); }
int64_t Exploration::planning_steps() const { return state_->env.planning_steps(); }
int64_t Exploration::visited() const { return state_->env.visited(); }
int64_t Exploration::free_cells() const { return state_->env.free_cells(); }
double Exploration::eP() const { return state_->env.eP(); }
double Exploration::sTime() const { return state_->env.sTime(); }
std::optional<int64_t> Exploration::completion_step() const { return state_->env.completion_step(); }
Cell Exploration::cell(CellIndex c) const { return state_->env.cell(c); }
const Scenario& Exploration::scenario() const { return state_->env.scenario(); }

StepRecord Exploration::record() const {
  const State& st = *state_;
  StepRecord r;
  r.step = st.env.tick();
  r.planning_steps = st.env.planning_steps();
  r.handshake = st.env.handshake();
  r.visited = st.env.visited();
  r.free_cells = st.env.free_cells();
  r.eP = st.env.eP();
  r.sTime = st.env.sTime();
  r.pheromone_digest = st.env.digest();
  for (std::size_t k = 0; k < st.body.size(); ++k)
    r.robots.push_back(RobotRecord{st.env.cells()[k], st.env.waypoints()[k], st.body[k], st.ctrl[k]});
  return r;
}

}  // namespace swarmcheck
