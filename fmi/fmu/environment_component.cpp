// The Environment FMU: impl's Environment (the spec's Environment step on the lazy grid) for N
// robots and M obstacle cells fixed at export. Its parameters make a scenario (validated as a
// scenario file is, at fmi2ExitInitializationMode); each doStep is one Environment step:
//   handshake 0: the thesis's flag handshake on all_arrived = every onDestination{i}Input is 1
//   handshake 1: the epoch handshake (spec epoch_environment_rule) on each robot's epochAck{i} and
//                onDestination{i}Input (its controller's `done`)
// The robots' poses x_i, y_i are inputs as in the thesis's table; the spec's Environment plans
// on the cells it moved the robots to, so they are recorded, not used.
//
// The saved state: the variables, and the run's decisions (environment_run.hpp).
#include <bit>
#include <cmath>
#include <optional>

#include "fmi/fmu/environment_run.hpp"
#include "fmi/fmu/kinds.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/scenario.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

class EnvironmentComponent final : public Component {
 public:
  explicit EnvironmentComponent(const FmuSetup& setup)
      : Component("environment"),
        base_(setup.scenario),
        robot_params_(static_cast<std::size_t>(setup.robots)),
        robot_in_(static_cast<std::size_t>(setup.robots)),
        robot_out_(static_cast<std::size_t>(setup.robots)),
        obstacles_(static_cast<std::size_t>(setup.obstacles)) {
    table_.bind(constants_, Role::constant);
    table_.bind(params_, Role::parameter);
    table_.bind(out_, Role::output);
    table_.bind(local_, Role::local);
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
    constants_ = {static_cast<int32_t>(robot_in_.size()), static_cast<int32_t>(obstacles_.size())};
    params_ = {s.map_size, s.cell_size, p.step_size, p.s_range, p.a1, p.a2, p.epsilon, p.ertu, p.eta, p.max_ph,
               p.phi, p.lambda, static_cast<int32_t>(s.rule), static_cast<int32_t>(s.seed), 0};
    for (std::size_t i = 0; i < robot_in_.size(); ++i) {
      robot_params_[i] = {s.robots[i][0], s.robots[i][1]};
      robot_in_[i] = {s.robots[i][0], s.robots[i][1], 1, 0};
      robot_out_[i] = {s.robots[i][0], s.robots[i][1]};
    }
    for (std::size_t m = 0; m < obstacles_.size(); ++m) obstacles_[m] = {s.obstacles[m][0], s.obstacles[m][1]};
    out_ = {0, 0.0, 0.0, 0, 0};
    local_ = {0, 1};
    run_.clear();
  }

  void initialize() override {
    run_.start(scenario());
    refresh();
  }

  void step(double /*t_s*/, double h_s) override {
    if (!run_.started()) throw FmuError("doStep before the Environment was initialised");
    const int64_t steps = environment_steps_in(h_s, params_.step_size);
    if (run_.state().tick + steps > ex::kStepsMax) throw FmuError("doStep: the Environment has taken its last step (2^31 - 1)");
    for (int64_t k = 0; k < steps; ++k) {   // the inputs stay as they are over the communication step
      run_.step(params_.handshake == 0 ? all_arrived() : epoch_verdict(), params_.handshake == 1);
      refresh();
    }
  }

 protected:
  void save_extra(std::vector<uint8_t>& out) const override { run_.save(out); }
  // The parameters are restored already: rebuild and replay. Outputs come back as saved.
  void restore_extra(std::span<const uint8_t>& in) override {
    run_.restore(in, [&] { return scenario(); }, params_.handshake == 1);
  }

 private:
  // The parameters as a scenario, checked as a scenario file is (FmuError naming the parameter's
  // scenario key when they do not make one).
  ex::Scenario scenario() const {
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
    if (params_.rule < 0 || params_.rule > 2) throw FmuError("rule: expected 0 (thesis), 1 (deterministic) or 2 (stochastic)");
    s.rule = static_cast<ex::RuleSet>(params_.rule);
    if (params_.seed < 0) throw FmuError("seed: expected an integer >= 0");
    s.seed = static_cast<uint64_t>(params_.seed);
    if (params_.handshake != 0 && params_.handshake != 1) throw FmuError("handshake: expected 0 (flag) or 1 (epoch)");
    s.mode = ex::Mode::cosim;
    for (std::size_t i = 0; i < robot_params_.size(); ++i) s.robots[i] = {robot_params_[i].lx_, robot_params_[i].ly_};
    for (std::size_t m = 0; m < obstacles_.size(); ++m) s.obstacles[m] = {obstacles_[m].ox_, obstacles_[m].oy_};
    validate_parameters(s, "mapSize, cellSize, lx_i/ly_i, ox_k/oy_k and the algorithm's parameters are its keys");
    return s;
  }

  bool all_arrived() const {
    return ex::all_arrived_rule<num::Concrete>(robot_in_.size(), [&](std::size_t k) {
      return robot_in_[k].onDestination__Input == 1;
    });
  }

  bool epoch_verdict() const {
    std::vector<int32_t> acks(robot_in_.size());
    const std::unique_ptr<bool[]> done(new bool[robot_in_.size()]);
    for (std::size_t k = 0; k < robot_in_.size(); ++k) {
      acks[k] = robot_in_[k].epochAck;
      done[k] = robot_in_[k].onDestination__Input == 1;
    }
    return ex::epoch_environment_rule<num::Concrete>(out_.epoch, acks, std::span<const bool>(done.get(), acks.size())).plan;
  }

  void refresh() {
    const ex::EnvironmentState& e = run_.state();
    out_.onDestinationOutput = e.handshake.on_destination_output;
    out_.eP = e.progress.eP;
    out_.sTime = e.progress.sTime;
    out_.epoch = static_cast<int32_t>(e.planning_steps % ex::kEpochs);
    out_.planningSteps = static_cast<int32_t>(e.planning_steps);
    local_ = {static_cast<int32_t>(e.tick), e.handshake.flag};
    for (std::size_t i = 0; i < robot_out_.size(); ++i)
      robot_out_[i] = {e.robots[i].waypoint[0], e.robots[i].waypoint[1]};
  }

  ex::Scenario base_;
  EnvironmentConstants constants_{};
  EnvironmentParameters params_{};
  EnvironmentOutputs out_{};
  EnvironmentLocals local_{};
  std::vector<EnvironmentRobotParameters> robot_params_;
  std::vector<EnvironmentRobotInputs> robot_in_;
  std::vector<EnvironmentRobotOutputs> robot_out_;
  std::vector<EnvironmentObstacleParameters> obstacles_;
  EnvironmentRun run_;
};

}  // namespace

std::unique_ptr<Component> make_environment_component(const FmuSetup& setup) {
  return std::make_unique<EnvironmentComponent>(setup);
}

}  // namespace swarmcheck::fmi
