#pragma once
// The counterexample writer of the mission harness: a (shrunk) mission as files that
// `swarmcheck mission run` loads, with the command that replays it and the first difference
// written into the mission's "about" text.
#include <string>

#include "spec/mission/run.hpp"

namespace swarmcheck::conformance::mission {

struct Counterexample {
  std::string mission_path;   // <dir>/<stem>.json
  std::string fsm_path;       // <dir>/<stem>.fsm, named by the mission relative to it
  std::string command;        // swarmcheck mission run <mission_path> --body ... --dt ...
};

// The mission as JSON text (spec/mission/mission.hpp's format), naming `fsm_file`.
std::string mission_json(const swarmcheck::mission::Mission& m, const std::string& fsm_file,
                         const std::string& about);

// Writes both files (each whole or not at all), creating dir.
Counterexample write_counterexample(const std::string& dir, const std::string& stem,
                                    const swarmcheck::mission::Mission& m,
                                    const swarmcheck::mission::RunOptions& o,
                                    const std::string& difference);

}  // namespace swarmcheck::conformance::mission
