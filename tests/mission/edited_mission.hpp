#pragma once
// Tests only: a committed mission file edited as JSON, written with its FSM into a fresh folder
// and loaded, so that a check's message can be compared with what the file would get.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "spec/util/input_error.hpp"
#include "swarmcheck/mission.hpp"

namespace swarmcheck::test {

using EditJson = std::function<void(nlohmann::ordered_json&)>;

// `mission_file` edited by `edit` and loaded as m.json beside a copy of `fsm_file` (the FSM
// name the mission gives) in a folder named after `tag` and the process; on an InputError,
// nothing, and the message after "m.json: " in *error (when error is given).
inline std::optional<swarmcheck::mission::Mission> load_edited(const std::string& tag,
                                                               const std::string& mission_file,
                                                               const std::string& fsm_file,
                                                               const EditJson& edit,
                                                               std::string* error = nullptr) {
  namespace fs = std::filesystem;
  const fs::path d = fs::temp_directory_path() / ("swarmcheck_" + tag + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  fs::copy_file(fsm_file, d / fs::path(fsm_file).filename(), fs::copy_options::overwrite_existing);
  std::ifstream in(mission_file);
  auto j = nlohmann::ordered_json::parse(in);
  edit(j);
  std::ofstream(d / "m.json") << j.dump(2);
  try {
    return swarmcheck::mission::load_mission((d / "m.json").string());
  } catch (const swarmcheck::InputError& e) {
    const std::string s = e.what();
    if (error) *error = s.substr(s.find("m.json: ") + 8);
    return std::nullopt;
  }
}

// The message load_edited gets, or "" when the edited mission loads.
inline std::string message_of_edited(const std::string& tag, const std::string& mission_file,
                                     const std::string& fsm_file, const EditJson& edit) {
  std::string error;
  return load_edited(tag, mission_file, fsm_file, edit, &error) ? std::string() : error;
}

}  // namespace swarmcheck::test
