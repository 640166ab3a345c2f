// A program using the swarmcheck library: run the thesis set-up in abstract mode.
#include <cstdio>
#include <swarmcheck/exploration.hpp>

int main() {
  swarmcheck::exploration::Scenario s = swarmcheck::exploration::default_scenario();
  s.mode = swarmcheck::exploration::Mode::abstract;
  swarmcheck::Exploration run(s);   // validates the scenario: throws swarmcheck::InputError
  while (!run.done()) run.step();
  std::printf("explored %.1f %% of %lld free cells in %lld steps\n", run.eP(),
              static_cast<long long>(run.free_cells()), static_cast<long long>(run.steps()));
  return run.completion_step() ? 0 : 1;
}
