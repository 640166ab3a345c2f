// Writing and reading mission traces (JSON Lines).
#include "impl/mission/trace.hpp"

#include <istream>
#include <memory>
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

MissionTrace read_trace(std::istream& in, const std::string& source) {
  MissionTrace t;
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty()) continue;
    const std::string where = source + ":" + std::to_string(n);
    try {
      const Json j = json_io::parse_json_text(line, source, static_cast<int64_t>(n));
      const std::string type = j.at("type").get<std::string>();
      if (type == "header") {
        t.initial_state = j.at("initial_state").get<std::string>();
        t.robots = j.at("robots").get<std::vector<std::string>>();
      } else if (type == "event") {
        TraceEntry e;
        e.is_event = true;
        e.event = EventRecord{j.at("t").get<double>(), j.at("event").get<std::string>(),
                              j.at("robot").get<std::string>(),
                              j.at("kind").get<std::string>() == "c",
                              j.at("state").get<std::string>()};
        t.entries.push_back(std::move(e));
      } else if (type == "step") {
        TraceEntry e;
        e.step.time_s = j.at("t").get<double>();
        e.step.state = j.at("state").get<std::string>();
        for (const auto& p : j.at("positions")) e.step.positions.push_back({p.at(0).get<double>(), p.at(1).get<double>()});
        for (const auto& b : j.at("blocked")) e.step.blocked.push_back(b.get<bool>());
        // Traces written before the yield rule have no "yielded": no robot yielded then.
        if (j.contains("yielded"))
          for (const auto& b : j.at("yielded")) e.step.yielded.push_back(b.get<bool>());
        else
          e.step.yielded.assign(e.step.blocked.size(), false);
        t.entries.push_back(std::move(e));
      } else if (type == "interval") {
        swarmcheck::mission::IntervalRecord i;
        i.robot = j.at("robot").get<std::string>();
        i.activity = json_io::enum_from_string<swarmcheck::mission::Activity>(
            j.at("activity").get<std::string>(), where + ": activity");
        i.from_s = j.at("from").get<double>();
        i.to_s = j.at("to").get<double>();
        t.intervals.push_back(std::move(i));
      } else {
        throw InputError(where, "unknown record type \"" + type + "\"");
      }
    } catch (const nlohmann::json::exception& e) {
      throw InputError(where, std::string("malformed trace record: ") + e.what());
    }
  }
  return t;
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
