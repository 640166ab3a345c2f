#include "conformance/supervisor/counterexample.hpp"

#include <filesystem>

#include "swarmcheck/supervisor.hpp"

namespace swarmcheck::conformance::supervisor {

std::vector<std::string> write_counterexample(const std::string& dir, const std::string& stem,
                                              const std::vector<swarmcheck::supervisor::Automaton>& automata) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < automata.size(); ++i) {
    const std::string path = dir + "/" + stem + "_" + std::to_string(i) + ".fsm";
    swarmcheck::supervisor::write_fsm_file(path, automata[i]);
    paths.push_back(path);
  }
  return paths;
}

}  // namespace swarmcheck::conformance::supervisor
