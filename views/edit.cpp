#include "views/edit.hpp"

#include <filesystem>

#include "swarmcheck/mission.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/mission/mission.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/json_text.hpp"
#include "views/schema.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {
namespace {

using json_io::Json;

Json scenario_for_editor(const swarmcheck::exploration::Scenario& s) { return json_io::to_json(s); }

}  // namespace

Page scenario_editor_page(const std::string& path) {
  const auto s = path.empty() ? swarmcheck::exploration::default_scenario()
                              : swarmcheck::exploration::load_scenario(path);
  Json data = {{"kind", "editor"}, {"file", path}, {"schema", scenario_schema()},
               {"scenario", scenario_for_editor(s)}, {"palette", exploration_palette()}};
  return Page{"swarmcheck scenario editor" + (path.empty() ? std::string() : ": " + path), data};
}

Page mission_editor_page(const std::string& path) {
  // The whole check of `mission plan` first; then the file as written (names, not indices).
  const swarmcheck::mission::Mission m = swarmcheck::mission::load_mission(path);
  Json decl = json_io::parse_json_text(read_text_file(path, "mission file"), path);
  Json states = Json::array();
  for (const auto& q : m.fsm.states) states.push_back(q);
  Json events = Json::array();
  for (const auto& [e, attr] : m.fsm.events) events.push_back({{"name", e}, {"controllable", attr.controllable}});
  Json data = {{"kind", "mission-editor"}, {"file", path}, {"mission", decl},
               {"fsm", {{"name", m.fsm_name}, {"states", states}, {"events", events}}},
               {"palette", exploration_palette()}};
  return Page{"swarmcheck mission editor: " + path, data};
}

Page edit_page(const std::string& path) {
  if (path.empty()) return scenario_editor_page(path);
  const Json j = json_io::parse_json_text(read_text_file(path, "file to edit"), path);
  if (j.is_object() && j.contains("fsm")) return mission_editor_page(path);
  return scenario_editor_page(path);
}

Page live_page() {
  Page p = scenario_editor_page("");
  p.title = "swarmcheck live";
  p.data["kind"] = "live";
  return p;
}

}  // namespace swarmcheck::views
