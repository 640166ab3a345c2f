#pragma once
// Loading a mission file: the JSON, the FSM it names (relative to the mission file's folder),
// and every check of spec::mission::check_mission. Bad input is an InputError.
#include <string>

#include "spec/mission/mission.hpp"

namespace swarmcheck::impl::mission {

spec::mission::Mission load_mission(const std::string& path);

}  // namespace swarmcheck::impl::mission
