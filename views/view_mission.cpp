// The mission trace view: regions, tasks, robots' paths over time, events on a timeline with the
// supervisor's state after each, robots waiting at a disabled region shown as waiting.
#include <filesystem>
#include <fmt/format.h>
#include <optional>
#include <sstream>
#include <string>

#include "swarmcheck/mission.hpp"
#include "impl/mission/trace.hpp"
#include "spec/util/input_error.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {
namespace {

namespace sm = swarmcheck::mission;
using json_io::Json;

Json point(const sm::Point& p) { return Json::array({p[0], p[1]}); }

// --mission, else the file of the header's mission name in the trace's own folder. The path the
// header names is never opened as written: a trace is data, and one naming /etc/shadow or
// ../../secret must not make `view` open it (and echo its first byte in a message).
std::string named_mission_file(const Json& header, const std::string& path, const ViewOptions& o) {
  if (!o.mission_path.empty()) return o.mission_path;
  const std::string named = json_io::string_member(header, "mission");
  if (named.empty()) throw InputError(path + ":1", "the header names no mission file; give it with --mission FILE");
  const std::filesystem::path name = std::filesystem::path(named).filename();
  const auto beside = std::filesystem::path(path).parent_path() / name;
  if (!name.empty() && name != "." && name != ".." && std::filesystem::is_regular_file(beside)) return beside.string();
  throw InputError(path + ":1", "the mission file of the header (\"" + named + "\") is looked up next to the trace, as " +
                                    beside.string() + ", and is not there; give it with --mission FILE");
}

sm::Mission load_named_mission(const Json& header, const std::string& path, const ViewOptions& o) {
  return swarmcheck::mission::load_mission(named_mission_file(header, path, o));
}

Json mission_json(const sm::Mission& m) {
  Json robots = Json::array(), tasks = Json::array(), regions = Json::array(), events = Json::object();
  for (const auto& r : m.robots) robots.push_back({{"name", r.name}, {"start", point(r.start)}});
  for (const auto& t : m.tasks) tasks.push_back({{"name", t.name}, {"at", point(t.at)}});
  for (const auto& g : m.regions) regions.push_back({{"name", g.name}, {"lo", point(g.lo)}, {"hi", point(g.hi)}});
  for (const auto& [e, meaning] : m.events) {
    const bool task = meaning.kind == sm::MeaningKind::task_start;
    events[e] = {{"robot", m.robots[meaning.robot].name},
                 {task ? "task" : "region", task ? m.tasks[meaning.target].name : m.regions[meaning.target].name}};
  }
  return {{"fsm", m.fsm_name}, {"initial_state", m.initial_state}, {"marked_states", m.marked_states},
          {"robots", robots}, {"tasks", tasks}, {"regions", regions}, {"events", events}};
}

}  // namespace

std::string mission_file_of_trace(const std::string& text, const std::string& path, const ViewOptions& o) {
  return named_mission_file(json_lines(text.substr(0, text.find('\n')), path).front().json, path, o);
}

Page mission_page(const std::string& text, const std::string& path, const ViewOptions& o) {
  if (o.max_records < 2) throw InputError("--max-records", "expected an integer >= 2");
  std::istringstream in(text);
  const impl::mission::MissionTrace t = impl::mission::read_trace(in, path);
  const Json header = json_lines(text.substr(0, text.find('\n')), path).front().json;
  const sm::Mission m = load_named_mission(header, path, o);
  impl::mission::check_trace_against_mission(t, m, path);
  std::vector<const impl::mission::StepRecord*> steps;
  Json events = Json::array();
  for (const auto& e : t.entries) {
    if (e.is_event) {
      events.push_back({{"t", e.event.time_s}, {"event", e.event.event}, {"robot", e.event.robot},
                        {"kind", e.event.controllable ? "c" : "uc"}, {"state", e.event.state_after}});
    } else {
      if (e.step.positions.size() != m.robots.size() || e.step.blocked.size() != m.robots.size())
        throw InputError(path, fmt::format("a step record at t={} does not have {} positions and blocked flags", e.step.time_s, m.robots.size()));
      steps.push_back(&e.step);
    }
  }
  if (steps.empty()) throw InputError(path, "the trace has no step record");
  // Thin evenly, keeping the last step and every step where a robot starts or stops waiting.
  const double stride = steps.size() <= static_cast<std::size_t>(o.max_records)
                            ? 1.0 : static_cast<double>(steps.size() - 1) / static_cast<double>(o.max_records - 1);
  Json time = Json::array(), state = Json::array(), xs = Json::array(), ys = Json::array(), blocked = Json::array();
  for (std::size_t r = 0; r < m.robots.size(); ++r) {
    xs.push_back(Json::array());
    ys.push_back(Json::array());
    blocked.push_back(Json::array());
  }
  double next = 0.0;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const bool change = k > 0 && steps[k]->blocked != steps[k - 1]->blocked;
    if (!(k + 1 == steps.size() || static_cast<double>(k) >= next || change)) continue;
    while (next <= static_cast<double>(k)) next += stride;
    time.push_back(steps[k]->time_s);
    state.push_back(steps[k]->state);
    for (std::size_t r = 0; r < m.robots.size(); ++r) {
      xs[r].push_back(steps[k]->positions[r][0]);
      ys[r].push_back(steps[k]->positions[r][1]);
      blocked[r].push_back(static_cast<bool>(steps[k]->blocked[r]));
    }
  }
  Json data = {{"kind", "mission"}, {"file", path}, {"header", header}, {"mission", mission_json(m)},
               {"palette", exploration_palette()}, {"events", events},
               {"steps", {{"t", time}, {"state", state}, {"x", xs}, {"y", ys}, {"blocked", blocked}}},
               {"steps_total", steps.size()}};
  return Page{"swarmcheck mission trace: " + path, data};
}

}  // namespace swarmcheck::views
