#include "conformance/exploration/trace_io.hpp"

#include <algorithm>
#include <fstream>
#include <type_traits>

#include "impl/io/atomic_file.hpp"
#include "conformance/exploration/observe.hpp"
#include "model/exploration/exploration_model.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/exploration/trace_field.hpp"
#include "spec/util/budget.hpp"
#include "spec/util/hana_diff.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::conformance::exploration {

using namespace swarmcheck::exploration;
using json_io::Json;

void write_counterexample(const std::string& path, const ExplorationCase& c, const Divergence& d) {
  Scenario s = c.scenario;
  s.max_steps = d.step;   // the trace ends where the engines part
  Json header = trace_header(s);
  header["impl_options"] = {{"grouped", c.grouped}};
  header["divergence"] = {{"step", d.step}, {"path", d.path}, {"model", d.model}, {"impl", d.impl},
                          {"spec_violation", d.spec_violation}, {"text", d.describe()}};
  // A run that ended abnormally (a crash, a hang): the records are the model's up to that step.
  if (!d.abnormal_end.empty()) header["divergence"]["abnormal_end"] = d.abnormal_end;
  impl::io::AtomicFile file(path);
  std::ofstream& out = file.stream();
  out << header.dump() << '\n';
  swarmcheck::model::exploration::ExplorationModel m(s);
  out << trace_line(m.record()) << '\n';
  while (m.steps() < d.step) {
    m.step();
    out << trace_line(m.record()) << '\n';
  }
  file.commit();
}

namespace {

// One JSON Lines record: errors at path:line:col (nesting, repeated keys, 1e400 included).
Json parse_line(const std::string& text, const std::string& path, int64_t lineno) {
  return json_io::parse_json_text(text, path, lineno);
}

struct TraceHeader {
  Scenario scenario;
  ExplorationOptions options;
  std::optional<std::string> recorded;
  // A counterexample's divergence in an output besides the records (observe.hpp): its step, path
  // and the model's value, re-checked after the records.
  std::optional<Divergence> derived;
};

// A member of a header object that must have one JSON type when present (absent: `fallback`).
template <class T>
T typed_member(const Json& o, const char* key, T fallback, const std::string& where, const char* expected) {
  if (!o.is_object() || !o.contains(key)) return fallback;
  const Json& v = o[key];
  const bool ok = std::is_same_v<T, bool> ? v.is_boolean() : std::is_same_v<T, std::string> ? v.is_string() : v.is_number_integer();
  if (!ok) throw InputError(where, std::string("header: ") + key + ": expected " + expected);
  return v.get<T>();
}

TraceHeader read_header(const Json& h, const std::string& where) {
  if (!h.is_object() || typed_member<std::string>(h, "format", "", where, "\"swarmcheck-trace\"") != "swarmcheck-trace")
    throw InputError(where, "expected a swarmcheck trace header ({\"format\": \"swarmcheck-trace\", ...})");
  if (typed_member<std::string>(h, "system", "", where, "\"exploration\"") != "exploration")
    throw InputError(where, "expected an exploration trace (\"system\": \"exploration\")");
  // A trace of another version would be read as if it were this one (absent: written before
  // the version was recorded, which is 1). Version 2 adds field records, which replay skips.
  if (const int64_t v = typed_member<int64_t>(h, "format_version", kTraceFormatVersion, where, "an integer");
      v != kTraceFormatVersion && v != kTraceFieldFormatVersion)
    throw InputError(where, "header: format_version: this swarmcheck reads versions " + std::to_string(kTraceFormatVersion) +
                                " and " + std::to_string(kTraceFieldFormatVersion) + ", got " + std::to_string(v));
  if (!h.contains("scenario")) throw InputError(where, "the header has no \"scenario\"");
  TraceHeader t;
  try {
    t.scenario = scenario_from_json(h["scenario"]);
  } catch (const InputError& e) {
    throw InputError(where, std::string("header: ") + e.what());
  }
  if (h.contains("impl_options") && !h["impl_options"].is_object())
    throw InputError(where, "header: impl_options: expected an object");
  if (typed_member<bool>(h.value("impl_options", Json::object()), "grouped", false, where, "true or false")) {
    t.options = grouped_options();
  }
  if (h.contains("divergence") && !h["divergence"].is_object())
    throw InputError(where, "header: divergence: expected an object");
  if (h.contains("divergence")) {
    const Json& d = h["divergence"];
    t.recorded = typed_member<std::string>(d, "text", "", where, "a string");
    const std::string derived_path = typed_member<std::string>(d, "path", "", where, "a string");
    if (d.contains("step") && d["step"].is_number_integer() && d.contains("model") && d["model"].is_string() &&
        is_derived_path(derived_path))
      t.derived = Divergence{d["step"].get<int64_t>(), derived_path, d["model"].get<std::string>(), "", false};
  }
  return t;
}

// Steps an engine to a given step and returns its record.
template <class Sim>
StepRecord record_at(Sim& sim, int64_t step) {
  while (sim.steps() < step && !sim.done()) sim.step();
  return sim.record();
}

// After the records: the output a counterexample's divergence names, at its step.
template <class Sim>
void recheck_derived(Sim& sim, const Divergence& recorded, ReplayResult& result) {
  if (sim.steps() != recorded.step) return;
  const std::string now = observe(sim, recorded.path).value_or("?");
  if (now != recorded.model) result.divergence = Divergence{recorded.step, recorded.path, recorded.model, now, false};
}

template <class Sim>
ReplayResult replay_with(Sim& sim, std::ifstream& in, const std::string& path, ReplayResult result,
                         const std::optional<Divergence>& derived) {
  std::string line;
  int64_t lineno = 1;
  int64_t last_step = -1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    StepRecord expected;
    const Json j = parse_line(line, path, lineno);   // its errors name path:line:col already
    try {
      if (json_io::string_member(j, "type") == "field") continue;  // format 2: field records
      json_io::from_json(j, "", expected);             // wrong types and unknown keys first,
      json_io::require_complete<StepRecord>(j, "");    // then nothing left out

    } catch (const InputError& e) {
      throw InputError(where, std::string("expected a step record: ") + e.what());
    }
    if (expected.step < sim.steps() || expected.step <= last_step)
      throw InputError(where, "records are not in increasing step order (step " + std::to_string(expected.step) +
                                  " after step " + std::to_string(std::max(last_step, sim.steps())) + ")");
    last_step = expected.step;
    const StepRecord actual = record_at(sim, expected.step);
    ++result.records;
    if (actual.step != expected.step) {
      result.divergence = Divergence{expected.step, "step", std::to_string(expected.step), std::to_string(actual.step), false};
      return result;
    }
    if (auto d = json_io::first_difference(expected, actual)) {
      result.divergence = Divergence{expected.step, d->path, d->a, d->b, false};
      return result;
    }
  }
  if (result.records == 0) throw InputError(path, "no step records after the header: nothing to replay");
  if (derived) recheck_derived(sim, *derived, result);
  return result;
}

}  // namespace

ReplayResult replay_trace(const std::string& path, Engine engine, std::uint64_t memory_limit_bytes) {
  io_input::check_input_file(path, "trace", false);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the trace");
  std::string first;
  if (!std::getline(in, first)) throw InputError(path + ":1", "empty file: expected a trace header");
  const TraceHeader h = read_header(parse_line(first, path, 1), path + ":1");
  const Scenario& s = h.scenario;
  require_within(path + ":1", "the trace's " + std::to_string(s.map_size) + " x " + std::to_string(s.map_size) + " map with " +
                                  std::to_string(s.robots.size()) + " robots",
                 static_cast<double>(estimated_bytes(engine, s)), memory_limit_bytes, "--memory-limit");
  ReplayResult result;
  result.recorded = h.recorded;
  const std::unique_ptr<Simulation> sim = make_simulation(engine, h.scenario, h.options);
  return replay_with(*sim, in, path, result, h.derived);
}

}  // namespace swarmcheck::conformance::exploration
