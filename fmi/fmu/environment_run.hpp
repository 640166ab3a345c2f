#pragma once
// What both Environment FMUs (environment_component.cpp: swarmcheck's interface;
// thesis_environment_component.cpp: the thesis's) run: impl's Environment (the spec's
// Environment step on the lazy grid) built from a scenario, one step per decision of the
// handshake (the flag handshake's all_arrived, or the epoch handshake's verdict), and its
// history of decisions. The Environment is a function of its scenario and that sequence, so a
// saved state is the decisions, one byte a step, and restoring rebuilds and replays: exact, and
// a state costs bytes, not the map.
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "spec/exploration/environment_step.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::impl::exploration {
class Environment;
}

namespace swarmcheck::fmi {

class EnvironmentRun {
 public:
  EnvironmentRun();
  ~EnvironmentRun();

  // (Re)builds the Environment for the scenario (fmi2ExitInitializationMode); no step taken.
  void start(const exploration::Scenario& s);
  void clear();   // back to not initialised (fmi2Reset)
  bool started() const { return env_ != nullptr; }
  const exploration::EnvironmentState& state() const;
  // One Environment step decided by `verdict`: `planned` false for the flag handshake (verdict:
  // every robot arrived), true when another protocol decided the planning (the epoch handshake).
  void step(bool verdict, bool planned);

  // The saved state's part: whether it is initialised, and the decisions.
  void save(std::vector<uint8_t>& out) const;
  // Reads what save() wrote (advancing `in`), then rebuilds with scenario() (the parameters are
  // restored already) and replays; FmuError if malformed.
  void restore(std::span<const uint8_t>& in, const std::function<exploration::Scenario()>& scenario, bool planned);

 private:
  std::unique_ptr<impl::exploration::Environment> env_;
  std::vector<uint8_t> history_;
};

// The Environment steps a communication step of h_s seconds takes: n when h_s is within a
// relative 1e-9 of n step_s (masters that compute a step as t(k+1) - t(k), as fmusim and FMPy do,
// give 0.10000000000000003 for 0.1). FmuError otherwise.
int64_t environment_steps_in(double h_s, double step_s);

// The scenario checked as a scenario file is: FmuError naming the parameters when it is not one.
void validate_parameters(const exploration::Scenario& s, const std::string& keys);

}  // namespace swarmcheck::fmi
