#include "conformance/exploration/engine.hpp"

#include "model/exploration/exploration_model.hpp"

namespace swarmcheck::conformance::exploration {
namespace {

using namespace swarmcheck::exploration;

class ModelSimulation final : public Simulation {
 public:
  explicit ModelSimulation(const Scenario& s) : m_(s) {}
  void step() override { m_.step(); }
  bool done() const override { return m_.done(); }
  int64_t steps() const override { return m_.steps(); }
  int64_t planning_steps() const override { return m_.planning_steps(); }
  int64_t visited() const override { return m_.visited(); }
  int64_t free_cells() const override { return m_.free_cells(); }
  double eP() const override { return m_.eP(); }
  double sTime() const override { return m_.sTime(); }
  std::optional<int64_t> completion_step() const override { return m_.completion_step(); }
  StepRecord record() const override { return m_.record(); }
  const Scenario& scenario() const override { return m_.scenario(); }
  Cell cell(CellIndex c) const override { return m_.cell(c); }

 private:
  swarmcheck::model::exploration::ExplorationModel m_;
};

class ImplSimulation final : public Simulation {
 public:
  template <class S>   // Scenario or ValidScenario
  ImplSimulation(const S& s, const ExplorationOptions& o) : x_(s, o) {}
  void step() override { x_.step(); }
  bool done() const override { return x_.done(); }
  int64_t steps() const override { return x_.steps(); }
  int64_t planning_steps() const override { return x_.planning_steps(); }
  int64_t visited() const override { return x_.visited(); }
  int64_t free_cells() const override { return x_.free_cells(); }
  double eP() const override { return x_.eP(); }
  double sTime() const override { return x_.sTime(); }
  std::optional<int64_t> completion_step() const override { return x_.completion_step(); }
  StepRecord record() const override { return x_.record(); }
  const Scenario& scenario() const override { return x_.scenario(); }
  Cell cell(CellIndex c) const override { return x_.cell(c); }

 private:
  Exploration x_;
};

}  // namespace

std::uint64_t estimated_bytes(Engine engine, const Scenario& s) {
  return engine == Engine::model ? swarmcheck::model::exploration::ExplorationModel::estimated_bytes(s)
                                 : Exploration::estimated_bytes(s);
}

std::unique_ptr<Simulation> make_simulation(Engine engine, const Scenario& s, const ExplorationOptions& options) {
  if (engine == Engine::model) return std::make_unique<ModelSimulation>(s);
  return std::make_unique<ImplSimulation>(s, options);
}

std::unique_ptr<Simulation> make_simulation(Engine engine, const ValidScenario& s, const ExplorationOptions& options) {
  if (engine == Engine::model) return std::make_unique<ModelSimulation>(s.get());
  return std::make_unique<ImplSimulation>(s, options);
}

swarmcheck::exploration::ExplorationOptions grouped_options() {
  swarmcheck::exploration::ExplorationOptions o;
  o.threads = 4;
  o.parallel_min_robots = 1;
  o.parallel_min_bodies = 1;
  o.walled_in_always = true;
  return o;
}

}  // namespace swarmcheck::conformance::exploration
