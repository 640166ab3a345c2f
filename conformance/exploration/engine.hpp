#pragma once
// The two engines of system A behind one interface: the reference model (the oracle) and the
// library users link. The command line (`run --engine`, `replay --against`) chooses between them
// here, so that only the harness ever reaches into model/.
#include <cstdint>
#include <memory>
#include <optional>

#include "spec/exploration/scenario.hpp"
#include "spec/exploration/types.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::conformance::exploration {

enum class Engine { model, impl };

class Simulation {
 public:
  virtual ~Simulation() = default;
  virtual void step() = 0;
  virtual bool done() const = 0;
  virtual int64_t steps() const = 0;
  virtual int64_t planning_steps() const = 0;
  virtual int64_t visited() const = 0;
  virtual int64_t free_cells() const = 0;
  virtual double eP() const = 0;
  virtual double sTime() const = 0;
  virtual std::optional<int64_t> completion_step() const = 0;
  virtual swarmcheck::exploration::StepRecord record() const = 0;
  virtual const swarmcheck::exploration::Scenario& scenario() const = 0;
  // One cell, its pheromone current at steps() (for the trace's field records).
  virtual swarmcheck::exploration::Cell cell(swarmcheck::exploration::CellIndex c) const = 0;
};

// About how many bytes the engine's run of `s` allocates (the memory budget's estimate).
std::uint64_t estimated_bytes(Engine engine, const swarmcheck::exploration::Scenario& s);

// The impl options of a "grouped" case: planning, deposits and bodies in parallel from the first
// robot, on more threads than this machine may have cores (the schedule must not depend on them),
// and every robot tested for being walled in, however sparse the swarm.
swarmcheck::exploration::ExplorationOptions grouped_options();

// `s` must be valid; `options` only matter to the impl.
std::unique_ptr<Simulation> make_simulation(Engine engine, const swarmcheck::exploration::Scenario& s,
                                            const swarmcheck::exploration::ExplorationOptions& options = {});
// The same for a scenario already validated (the impl does not validate it again).
std::unique_ptr<Simulation> make_simulation(Engine engine, const swarmcheck::exploration::ValidScenario& s,
                                            const swarmcheck::exploration::ExplorationOptions& options = {});

}  // namespace swarmcheck::conformance::exploration
