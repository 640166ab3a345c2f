// Loading a mission file and the FSM it names.
#include "swarmcheck/mission.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "swarmcheck/supervisor.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"

namespace swarmcheck::mission {

namespace {
std::filesystem::path fsm_path_of(const std::string& mission_path, const std::string& fsm) {
  return std::filesystem::path(mission_path).parent_path() / std::filesystem::path(fsm);
}
}  // namespace

std::vector<std::string> mission_input_files(const std::string& path) {
  const auto decl = parse_mission_text(io_input::read_input_file(path, "mission file"), path);
  return {path, fsm_path_of(path, decl.fsm).string()};
}

Mission load_mission(const std::string& path) {
  const auto decl = parse_mission_text(io_input::read_input_file(path, "mission file"), path);
  const std::filesystem::path fsm_path = fsm_path_of(path, decl.fsm);
  if (!std::filesystem::is_regular_file(fsm_path))
    throw InputError(path + ": fsm",
                     "cannot open the FSM file \"" + decl.fsm + "\" (looked for " +
                         fsm_path.string() + ")");
  const auto fsm = swarmcheck::supervisor::read_fsm_file(fsm_path.string());
  return check_mission(decl, fsm, path);
}

}  // namespace swarmcheck::mission
