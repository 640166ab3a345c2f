// The Environment FMU: impl's Environment (the spec's Environment step on the lazy grid) for N
// robots and M obstacle cells fixed at export. Its parameters make a scenario (validated as a
// scenario file is, at fmi2ExitInitializationMode); each doStep is one Environment step:
//   handshake 0: the thesis's flag handshake on all_arrived = every onDestination{i}Input is 1
//   handshake 1: the epoch handshake (spec epoch_environment_rule) on each robot's epochAck{i} and
//                onDestination{i}Input (its controller's `done`)
// The robots' poses x_i, y_i are inputs as in the thesis's table; the spec's Environment plans
// on the cells it moved the robots to, so they are recorded, not used.
//
// The saved state: the variables, and one byte per step taken (the input that decided the step:
// all_arrived, or the epoch verdict). The Environment is a function of its parameters and that
// sequence, so restoring rebuilds it and replays the steps: exact, and a state costs bytes, not
// the map.
#include <bit>
#include <cmath>
#include <optional>

#include "fmi/fmu/kinds.hpp"
#include "impl/exploration/environment.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;
using ImplEnvironment = swarmcheck::impl::exploration::Environment;

class EnvironmentComponent final : public Component {
 public:
  explicit EnvironmentComponent(const FmuSetup& setup)
      : base_(setup.scenario),
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
    env_.reset();
    history_.clear();
  }

  void initialize() override {
    env_.reset();
    history_.clear();
    env_ = std::make_unique<ImplEnvironment>(scenario(), ExplorationOptions{});
    refresh();
  }

  void step(double h_s) override {
    if (!env_) throw FmuError("doStep before the Environment was initialised");
    if (h_s != params_.step_size)
      throw FmuError("doStep: the communication step " + number(h_s) + " s differs from step_size " +
                     number(params_.step_size) + " s (this FMU steps at step_size only)");
    if (env_->state().tick >= ex::kStepsMax) throw FmuError("doStep: the Environment has taken its last step (2^31 - 1)");
    const bool verdict = params_.handshake == 0 ? all_arrived() : epoch_verdict();
    advance(verdict);
    history_.push_back(verdict ? 1 : 0);
    refresh();
  }

 protected:
  void save_extra(std::vector<uint8_t>& out) const override {
    out.push_back(env_ ? 1 : 0);
    put_state_u64(out, history_.size());
    out.insert(out.end(), history_.begin(), history_.end());
  }

  void restore_extra(std::span<const uint8_t>& in) override {
    if (in.empty()) throw FmuError("FMU state: the bytes end early (not a state of this FMU)");
    const bool initialised = in[0] == 1;
    in = in.subspan(1);
    const uint64_t steps = take_state_u64(in);
    if (steps > in.size()) throw FmuError("FMU state: the bytes end early (not a state of this FMU)");
    std::vector<uint8_t> history(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(steps));
    in = in.subspan(static_cast<std::size_t>(steps));
    if (!initialised && !history.empty()) throw FmuError("FMU state: steps recorded before initialisation");
    // The parameters are restored already: rebuild and replay. Outputs come back as saved.
    env_.reset();
    history_.clear();
    if (!initialised) return;
    env_ = std::make_unique<ImplEnvironment>(scenario(), ExplorationOptions{});
    for (const uint8_t verdict : history) advance(verdict == 1);
    history_ = std::move(history);
  }

 private:
  static std::string number(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
  }

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
    try {
      ex::validate(s);
    } catch (const InputError& e) {
      throw FmuError(std::string("the parameters do not make a valid scenario: ") + e.what() +
                     " (mapSize, cellSize, lx_i/ly_i, ox_k/oy_k and the algorithm's parameters are its keys)");
    }
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

  // One step whose decision is `verdict` (what the history records).
  void advance(bool verdict) {
    if (params_.handshake == 0) env_->step(verdict);
    else env_->step_planned(verdict);
  }

  void refresh() {
    const ex::EnvironmentState& e = env_->state();
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
  std::unique_ptr<ImplEnvironment> env_;
  std::vector<uint8_t> history_;
};

}  // namespace

std::unique_ptr<Component> make_environment_component(const FmuSetup& setup) {
  return std::make_unique<EnvironmentComponent>(setup);
}

}  // namespace swarmcheck::fmi
