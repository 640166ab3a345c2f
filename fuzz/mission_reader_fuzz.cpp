// libFuzzer target for the mission reader: the text -> checked mission path of load_mission
// (impl/mission/load.cpp), which `mission plan` and `mission run` start with: parse_mission_text,
// then check_mission against the supervisor the file names, then the plan's initial query. Any
// bytes either give a checked mission or raise one InputError; never another exception, a
// crash, a hang or a sanitizer report.
//
// No file system: the supervisors are the shipped .fsm files under scenarios/thesis, read once,
// and looked up by the "fsm" entry as written (relative to scenarios/thesis, where the shipped
// mission lives). load_mission refuses a name it cannot open before check_mission; here an
// unknown name is checked against control2.fsm instead, so the checks see more inputs.
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>

#include "impl/supervisor/fsm_io.hpp"
#include "spec/mission/mission.hpp"
#include "spec/mission/plan.hpp"
#include "spec/util/input_error.hpp"

#ifndef SWARMCHECK_SCENARIOS
#error "compile with -DSWARMCHECK_SCENARIOS=\"<source>/scenarios\""
#endif

namespace {

namespace sm = swarmcheck::mission;
namespace sv = swarmcheck::impl::supervisor;

// Every .fsm under scenarios/thesis, by its path relative to that folder ("control2.fsm",
// "components/region_a.fsm").
const std::map<std::string, sv::Automaton>& supervisors() {
  static const std::map<std::string, sv::Automaton> all = [] {
    namespace fs = std::filesystem;
    const fs::path root = fs::path(SWARMCHECK_SCENARIOS) / "thesis";
    std::map<std::string, sv::Automaton> out;
    for (const auto& e : fs::recursive_directory_iterator(root))
      if (e.is_regular_file() && e.path().extension() == ".fsm")
        out.emplace(e.path().lexically_relative(root).generic_string(), sv::read_fsm_file(e.path().string()));
    if (!out.count("control2.fsm")) std::abort();   // the harness's own set-up is broken
    return out;
  }();
  return all;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto& fsms = supervisors();
  try {
    const sm::MissionDecl d = sm::parse_mission_text(text, "fuzz-mission.json");
    const auto named = fsms.find(d.fsm);
    const sv::Automaton& fsm = named != fsms.end() ? named->second : fsms.at("control2.fsm");
    const sm::Mission m = sm::check_mission(d, fsm, "fuzz-mission.json");
    // What a checked mission promises (mission.hpp): one meaning per FSM event, a robot at least.
    if (m.robots.empty() || m.marked_states.empty()) std::abort();
    if (m.events.size() != m.fsm.events.size()) std::abort();
    for (const auto& [event, meaning] : m.events) {
      if (meaning.robot >= m.robots.size()) std::abort();
      const std::size_t targets =
          meaning.kind == sm::MeaningKind::task_start ? m.tasks.size() : m.regions.size();
      if (meaning.target >= targets) std::abort();
    }
    (void)sm::initial_entries(m);
    (void)sm::initial_query(m);
  } catch (const swarmcheck::InputError&) {
    // bad input, reported: the expected outcome for most inputs
  }
  return 0;
}
