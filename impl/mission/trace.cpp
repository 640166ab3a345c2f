// Writing and reading mission traces (JSON Lines).
#include "impl/mission/trace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <istream>
#include <memory>
#include <initializer_list>
#include <string_view>
#include <map>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <ostream>

#include "impl/io/atomic_file.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/json_text.hpp"
#include "swarmcheck/mission.hpp"

namespace swarmcheck::impl::mission {

namespace {
using Json = nlohmann::ordered_json;
}

TraceWriter::TraceWriter(std::ostream& out, const swarmcheck::mission::Mission& m, const RunOptions& o)
    : out_(out) {
  Json names = Json::array();
  for (const auto& r : m.robots) names.push_back(r.name);
  const Json h = {{"type", "header"},
                  {"format", "swarmcheck-mission-trace"},
                  {"version", 1},
                  {"mission", m.source},
                  {"fsm", m.fsm_name},
                  {"initial_state", m.initial_state},
                  {"robots", names},
                  {"body", json_io::enum_to_string(o.body)},
                  {"dt", o.dt_s}};
  out_ << json_io::dump_text(h) << '\n';   // the mission's path may not be UTF-8
}

void TraceWriter::on_event(const EventRecord& e) {
  const Json j = {{"type", "event"},  {"t", e.time_s},
                  {"event", e.event}, {"robot", e.robot},
                  {"kind", e.controllable ? "c" : "uc"}, {"state", e.state_after}};
  out_ << j.dump() << '\n';
}

void TraceWriter::on_step(const StepRecord& s) {
  Json pos = Json::array();
  for (const auto& p : s.positions) pos.push_back({p[0], p[1]});
  Json blocked = Json::array();
  for (const bool b : s.blocked) blocked.push_back(b);
  Json yielded = Json::array();
  for (const bool b : s.yielded) yielded.push_back(b);
  const Json j = {{"type", "step"}, {"t", s.time_s}, {"state", s.state},
                  {"positions", pos}, {"blocked", blocked}, {"yielded", yielded}};
  out_ << j.dump() << '\n';
}

void TraceWriter::on_interval(const swarmcheck::mission::IntervalRecord& i) {
  const Json j = {{"type", "interval"}, {"robot", i.robot},
                  {"activity", json_io::enum_to_string(i.activity)},
                  {"from", i.from_s}, {"to", i.to_s}};
  out_ << j.dump() << '\n';
}

namespace {

// A record's fields, each checked, with its JSON path in the message (the library's own text
// named neither the field nor the path).
class Record {
 public:
  Record(const Json& j, std::string where) : j_(j), where_(std::move(where)) {
    if (!j_.is_object()) throw InputError(where_, "expected a JSON object, got " + json_io::type_name(j_));
  }
  const Json& at(const char* key) const {
    const auto it = j_.find(key);
    if (it == j_.end()) throw InputError(where_ + ": " + key, "missing");
    return *it;
  }
  bool has(const char* key) const { return j_.contains(key); }
  // A field not among `known` is a mistake (a misspelt key would otherwise be read as absent).
  void only(std::initializer_list<std::string_view> known) const {
    for (const auto& [key, value] : j_.items())
      if (std::find(known.begin(), known.end(), key) == known.end()) {
        std::string list;
        for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        throw InputError(where_ + ": " + key, "unknown field (a " + j_.value("type", std::string("record")) + " record has " + list + ")");
      }
  }
  double number(const char* key) const { return number_at(at(key), key); }
  std::string text(const char* key) const {
    const Json& v = at(key);
    if (!v.is_string()) throw InputError(where_ + ": " + key, "expected a string, got " + json_io::type_name(v));
    return v.get<std::string>();
  }
  std::vector<bool> flags(const char* key) const {
    std::vector<bool> out;
    const Json& v = array(key);
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (!v[k].is_boolean())
        throw InputError(where_ + ": " + key + "[" + std::to_string(k) + "]", "expected true or false, got " + json_io::type_name(v[k]));
      out.push_back(v[k].get<bool>());
    }
    return out;
  }
  std::vector<std::string> texts(const char* key) const {
    std::vector<std::string> out;
    const Json& v = array(key);
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (!v[k].is_string())
        throw InputError(where_ + ": " + key + "[" + std::to_string(k) + "]", "expected a string, got " + json_io::type_name(v[k]));
      out.push_back(v[k].get<std::string>());
    }
    return out;
  }
  std::vector<std::array<double, 2>> points(const char* key) const {
    std::vector<std::array<double, 2>> out;
    const Json& v = array(key);
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::string path = std::string(key) + "[" + std::to_string(k) + "]";
      if (!v[k].is_array() || v[k].size() != 2)
        throw InputError(where_ + ": " + path, "expected [x, y], got " + (v[k].is_array() ? "a list of " + std::to_string(v[k].size())
                                                                                        : json_io::type_name(v[k])));
      out.push_back({number_at(v[k][0], path + "[0]"), number_at(v[k][1], path + "[1]")});
    }
    return out;
  }
  const std::string& where() const { return where_; }

 private:
  const Json& array(const char* key) const {
    const Json& v = at(key);
    if (!v.is_array()) throw InputError(where_ + ": " + key, "expected a list, got " + json_io::type_name(v));
    return v;
  }
  double number_at(const Json& v, const std::string& path) const {
    if (!v.is_number()) throw InputError(where_ + ": " + path, "expected a number, got " + json_io::type_name(v));
    return v.get<double>();
  }
  const Json& j_;
  std::string where_;
};

}  // namespace

MissionTrace read_trace(std::istream& in, const std::string& source) {
  MissionTrace t;
  std::string line;
  std::size_t n = 0;
  bool header = false;
  double last_t = 0;                     // of the last event or step
  std::optional<double> last_step_t;     // steps are one simulation step apart: strictly later
  std::map<std::string, double> last_interval_end;   // a robot's intervals follow one another
  while (std::getline(in, line)) {
    ++n;
    if (line.empty()) continue;
    const std::string where = source + ":" + std::to_string(n);
    const Json j = json_io::parse_json_text(line, source, static_cast<int64_t>(n));
    const Record rec(j, where);
    const std::string type = rec.text("type");
    if (type != "header" && !header) throw InputError(where, "a " + type + " record before the header");
    // A time of the record: finite, >= 0, and for events and steps not before the last one.
    const auto time = [&](const char* key, bool ordered) {
      const double v = rec.number(key);
      if (!std::isfinite(v) || v < 0) throw InputError(where + ": " + key, fmt::format("expected a time >= 0 s, got {}", v));
      if (ordered && v < last_t)
        throw InputError(where + ": " + key, fmt::format("expected records in time order, got {} after {}", v, last_t));
      if (ordered) last_t = v;
      return v;
    };
    const auto robot = [&](const char* key) {
      std::string name = rec.text(key);
      if (std::find(t.robots.begin(), t.robots.end(), name) == t.robots.end())
        throw InputError(where + ": " + key, "\"" + name + "\" is not a robot of the header");
      return name;
    };
    if (type == "header") {
      rec.only({"type", "format", "version", "mission", "fsm", "initial_state", "robots", "body", "dt"});
      if (header) throw InputError(where, "a second header");
      header = true;
      t.initial_state = rec.text("initial_state");
      t.robots = rec.texts("robots");
    } else if (type == "event") {
      rec.only({"type", "t", "event", "robot", "kind", "state"});
      TraceEntry e;
      e.line = n;
      e.is_event = true;
      const std::string kind = rec.text("kind");
      if (kind != "c" && kind != "uc") throw InputError(where + ": kind", "expected \"c\" or \"uc\", got \"" + kind + "\"");
      const double at = time("t", true);
      e.event = EventRecord{at, rec.text("event"), robot("robot"), kind == "c", rec.text("state")};
      t.entries.push_back(std::move(e));
    } else if (type == "step") {
      if (t.robots.empty()) throw InputError(where, "a step record before the header (or a header naming no robots)");
      rec.only({"type", "t", "state", "positions", "blocked", "yielded"});
      TraceEntry e;
      e.line = n;
      e.step.time_s = time("t", true);
      if (last_step_t && !(e.step.time_s > *last_step_t))
        throw InputError(where + ": t", fmt::format("expected a time after the last step's ({}), got {}", *last_step_t, e.step.time_s));
      last_step_t = e.step.time_s;
      e.step.state = rec.text("state");
      for (const auto& p : rec.points("positions")) e.step.positions.push_back({p[0], p[1]});
      e.step.blocked = rec.flags("blocked");
      // Traces written before the yield rule have no "yielded": no robot yielded then.
      e.step.yielded = rec.has("yielded") ? rec.flags("yielded") : std::vector<bool>(e.step.blocked.size(), false);
      if (e.step.positions.size() != t.robots.size() || e.step.blocked.size() != t.robots.size() ||
          e.step.yielded.size() != t.robots.size())
        throw InputError(where, "a step record has " + std::to_string(e.step.positions.size()) + " positions, " +
                                    std::to_string(e.step.blocked.size()) + " blocked and " +
                                    std::to_string(e.step.yielded.size()) + " yielded flags; the header names " +
                                    std::to_string(t.robots.size()) + " robots");
      t.entries.push_back(std::move(e));
    } else if (type == "interval") {
      swarmcheck::mission::IntervalRecord i;
      rec.only({"type", "robot", "activity", "from", "to"});
      i.robot = robot("robot");
      i.activity = json_io::enum_from_string<swarmcheck::mission::Activity>(rec.text("activity"), where + ": activity");
      i.from_s = time("from", false);
      i.to_s = time("to", false);
      if (i.to_s < i.from_s) throw InputError(where + ": to", fmt::format("expected a time >= from ({}), got {}", i.from_s, i.to_s));
      const auto [previous, first] = last_interval_end.try_emplace(i.robot, i.to_s);
      if (!first) {
        if (i.from_s < previous->second)
          throw InputError(where + ": from", fmt::format("expected a time >= {} (where robot {}'s last interval ended), got {}",
                                                         previous->second, i.robot, i.from_s));
        previous->second = i.to_s;
      }
      t.intervals.push_back(std::move(i));
    } else {
      throw InputError(where, "unknown record type \"" + type + "\"");
    }
  }
  return t;
}

void check_trace_against_mission(const MissionTrace& t, const swarmcheck::mission::Mission& m, const std::string& path) {
  if (t.robots.size() != m.robots.size())
    throw InputError(path + ":1", fmt::format("the trace has {} robots, the mission {}", t.robots.size(), m.robots.size()));
  for (std::size_t r = 0; r < m.robots.size(); ++r)
    if (t.robots[r] != m.robots[r].name)
      throw InputError(path + ":1: robots[" + std::to_string(r) + "]",
                       "expected \"" + m.robots[r].name + "\" (the mission's robot " + std::to_string(r + 1) + "), got \"" + t.robots[r] + "\"");
  if (t.initial_state != m.initial_state)
    throw InputError(path + ":1: initial_state", "expected the mission's \"" + m.initial_state + "\", got \"" + t.initial_state + "\"");
  std::string state = m.initial_state;
  for (const auto& e : t.entries) {
    const std::string where = path + ":" + std::to_string(e.line);
    if (!e.is_event) {
      if (e.step.state != state)
        throw InputError(where + ": state", "expected \"" + state + "\" (where the events so far lead), got \"" + e.step.state + "\"");
      continue;
    }
    const auto meaning = m.events.find(e.event.event);
    if (meaning == m.events.end())
      throw InputError(where + ": event", "\"" + e.event.event + "\" is not an event of " + m.fsm_name);
    const std::string& robot = m.robots[meaning->second.robot].name;
    if (e.event.robot != robot)
      throw InputError(where + ": robot", "expected \"" + robot + "\" (" + e.event.event + " is robot " + robot + "'s), got \"" + e.event.robot + "\"");
    const bool controllable = m.fsm.events.at(e.event.event).controllable;
    if (e.event.controllable != controllable)
      throw InputError(where + ": kind", fmt::format("expected \"{}\" ({} is {} in {}), got \"{}\"", controllable ? "c" : "uc",
                                                     e.event.event, controllable ? "controllable" : "uncontrollable", m.fsm_name,
                                                     e.event.controllable ? "c" : "uc"));
    const std::optional<std::string> next = swarmcheck::supervisor::successor(m.fsm, state, e.event.event);
    if (!next)
      throw InputError(where + ": event", "\"" + e.event.event + "\" is not enabled in state \"" + state + "\" of " + m.fsm_name);
    if (*next != e.event.state_after)
      throw InputError(where + ": state", "expected \"" + *next + "\" (" + e.event.event + " from \"" + state + "\" in " +
                                             m.fsm_name + "), got \"" + e.event.state_after + "\"");
    state = *next;
  }
}

}  // namespace swarmcheck::impl::mission

namespace swarmcheck::mission {

// The writer is built on the temporary file's stream, so the file is declared first.
struct TraceFile::State {
  State(const std::string& path, const Mission& m, const RunOptions& o)
      : file(path), writer(file.stream(), m, o) {}
  impl::io::AtomicFile file;
  impl::mission::TraceWriter writer;
};

TraceFile::TraceFile(const std::string& path, const Mission& m, const RunOptions& o)
    : state_(std::make_unique<State>(path, m, o)) {}
TraceFile::~TraceFile() = default;
void TraceFile::on_event(const EventRecord& e) { state_->writer.on_event(e); }
void TraceFile::on_step(const StepRecord& s) { state_->writer.on_step(s); }
void TraceFile::on_interval(const IntervalRecord& i) { state_->writer.on_interval(i); }
void TraceFile::commit() { state_->file.commit(); }

}  // namespace swarmcheck::mission
