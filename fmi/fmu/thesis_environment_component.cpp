// The Environment FMU of the thesis interface (thesis_ports.hpp): swarmcheck's Environment
// (environment_run.hpp, the scenario's rule set: `thesis` unless the export's scenario says
// otherwise) behind the variables of the thesis's own Environment FMU, with the thesis's flag
// handshake on Real ports: each doStep is one Environment step (or n for a step of n step_size)
// on all_arrived = every taking-part robot's onDestination{i}Input is 1.0.
//   - N robots and M obstacle slots are fixed at export; the first nRobots and nObstacles take
//     part (a robot that does not keeps its outputs at its start position).
//   - flag and stepCount are the thesis's handshake flag and step counter at start, parameters
//     in its FMU: swarmcheck's Environment starts them at 1 and 0 only, and refuses others.
//   - port is the thesis's live-view port: accepted, unused (this Environment opens no socket).
// The saved state: the variables and the run's decisions (environment_run.hpp).
#include <cmath>

#include "fmi/fmu/environment_run.hpp"
#include "fmi/fmu/kinds.hpp"
#include "fmi/fmu/thesis_ports.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

class ThesisEnvironmentComponent final : public Component {
 public:
  explicit ThesisEnvironmentComponent(const FmuSetup& setup)
      : Component("thesis environment"),
        base_(setup.scenario),
        robot_params_(static_cast<std::size_t>(setup.robots)),
        robot_in_(static_cast<std::size_t>(setup.robots)),
        robot_out_(static_cast<std::size_t>(setup.robots)),
        obstacles_(static_cast<std::size_t>(setup.obstacles)) {
    table_.bind(params_, Role::parameter);
    table_.bind(out_, Role::output);
    for (std::size_t i = 0; i < robot_in_.size(); ++i) {
      const auto k = static_cast<int32_t>(i + 1);
      table_.bind(robot_params_[i], Role::parameter, k);
      table_.bind(robot_in_[i], Role::input, k);
      table_.bind(robot_out_[i], Role::output, k);
    }
    for (std::size_t m = 0; m < obstacles_.size(); ++m)
      table_.bind(obstacles_[m], Role::parameter, static_cast<int32_t>(m + 1));
  }

  void defaults() override {
    const ex::Scenario& s = base_;
    const ex::Params& p = s.params;
    params_ = {p.a1, p.a2, p.ertu, p.eta, 1, p.lambda, s.map_size, p.max_ph, static_cast<int32_t>(s.robots.size()), p.phi,
               8087, p.s_range, p.step_size, 0, static_cast<int32_t>(s.obstacles.size()), s.cell_size, p.epsilon,
               static_cast<int32_t>(s.rule), static_cast<int32_t>(s.seed)};
    for (std::size_t i = 0; i < robot_in_.size(); ++i) {
      robot_params_[i] = {s.robots[i][0], s.robots[i][1]};
      robot_in_[i] = {1.0, s.robots[i][0], s.robots[i][1]};
      robot_out_[i] = {s.robots[i][0], s.robots[i][1]};
    }
    for (std::size_t m = 0; m < obstacles_.size(); ++m)
      obstacles_[m] = m < s.obstacles.size() ? EnvironmentObstacleParameters{s.obstacles[m][0], s.obstacles[m][1]}
                                             : EnvironmentObstacleParameters{0, 0};
    out_ = {0.0, 0.0, 0.0};
    run_.clear();
  }

  void initialize() override {
    run_.start(scenario());
    for (std::size_t i = 0; i < robot_out_.size(); ++i) robot_out_[i] = {robot_params_[i].lx_, robot_params_[i].ly_};
    refresh();
  }

  void step(double /*t_s*/, double h_s) override {
    if (!run_.started()) throw FmuError("doStep before the Environment was initialised");
    const int64_t steps = environment_steps_in(h_s, params_.step_size);
    if (run_.state().tick + steps > ex::kStepsMax) throw FmuError("doStep: the Environment has taken its last step (2^31 - 1)");
    for (int64_t k = 0; k < steps; ++k) {   // the inputs stay as they are over the communication step
      run_.step(all_arrived(), false);
      refresh();
    }
  }

 protected:
  void save_extra(std::vector<uint8_t>& out) const override { run_.save(out); }
  // The parameters are restored already: rebuild and replay. Outputs come back as saved.
  void restore_extra(std::span<const uint8_t>& in) override {
    run_.restore(in, [&] { return scenario(); }, false);
  }

 private:
  std::size_t taking_part() const { return static_cast<std::size_t>(params_.nRobots); }

  // The parameters as a scenario, checked as a scenario file is.
  ex::Scenario scenario() const {
    const auto n = static_cast<int32_t>(robot_params_.size()), m = static_cast<int32_t>(obstacles_.size());
    if (params_.nRobots < 1 || params_.nRobots > n)
      throw FmuError("nRobots: expected 1.." + std::to_string(n) + " (this FMU's robots, fixed at export), got " +
                     std::to_string(params_.nRobots));
    if (params_.nObstacles < 0 || params_.nObstacles > m)
      throw FmuError("nObstacles: expected 0.." + std::to_string(m) + " (this FMU's obstacle slots, fixed at export), got " +
                     std::to_string(params_.nObstacles));
    if (params_.flag != 1) throw FmuError("flag: swarmcheck's Environment starts its handshake flag at 1, got " + std::to_string(params_.flag));
    if (params_.stepCount != 0)
      throw FmuError("stepCount: swarmcheck's Environment counts its steps from 0, got " + std::to_string(params_.stepCount));
    if (params_.rule < 0 || params_.rule > 2) throw FmuError("rule: expected 0 (thesis), 1 (deterministic) or 2 (stochastic)");
    if (params_.seed < 0) throw FmuError("seed: expected an integer >= 0");
    ex::Scenario s = base_;
    s.map_size = params_.mapSize;
    s.cell_size = params_.cellSize;
    s.params.step_size = params_.step_size;
    s.params.s_range = params_.s_range;
    s.params.a1 = params_.a1;
    s.params.a2 = params_.a2;
    s.params.epsilon = params_.epsilon;
    s.params.ertu = params_.ertu_perc;
    s.params.eta = params_.eta;
    s.params.max_ph = params_.max_ph;
    s.params.phi = params_.phi;
    s.params.lambda = params_.lambda;
    s.rule = static_cast<ex::RuleSet>(params_.rule);
    s.seed = static_cast<uint64_t>(params_.seed);
    s.mode = ex::Mode::cosim;
    s.robots.clear();
    for (std::size_t i = 0; i < taking_part(); ++i) s.robots.push_back({robot_params_[i].lx_, robot_params_[i].ly_});
    s.obstacles.clear();
    for (std::size_t k = 0; k < static_cast<std::size_t>(params_.nObstacles); ++k)
      s.obstacles.push_back({obstacles_[k].ox_, obstacles_[k].oy_});
    validate_parameters(s, "mapSize, cellSize, lx_i/ly_i and ox_k/oy_k of the robots and obstacles taking part, and the "
                           "algorithm's parameters are its keys");
    return s;
  }

  bool all_arrived() const {
    return ex::all_arrived_rule<num::Concrete>(taking_part(), [&](std::size_t k) {
      return robot_in_[k].onDestination__Input == 1.0;
    });
  }

  void refresh() {
    const ex::EnvironmentState& e = run_.state();
    out_.onDestinationOutput = e.handshake.on_destination_output == 1 ? 1.0 : 0.0;
    out_.eP = e.progress.eP;
    out_.sTime = e.progress.sTime;
    for (std::size_t i = 0; i < taking_part(); ++i) robot_out_[i] = {e.robots[i].waypoint[0], e.robots[i].waypoint[1]};
  }

  ex::Scenario base_;
  ThesisEnvironmentParameters params_{};
  ThesisEnvironmentOutputs out_{};
  std::vector<EnvironmentRobotParameters> robot_params_;
  std::vector<ThesisEnvironmentRobotInputs> robot_in_;
  std::vector<ThesisEnvironmentRobotOutputs> robot_out_;
  std::vector<EnvironmentObstacleParameters> obstacles_;
  EnvironmentRun run_;
};

}  // namespace

std::unique_ptr<Component> make_thesis_environment_component(const FmuSetup& setup) {
  return std::make_unique<ThesisEnvironmentComponent>(setup);
}

}  // namespace swarmcheck::fmi
