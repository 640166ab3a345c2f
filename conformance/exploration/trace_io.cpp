#include "conformance/exploration/trace_io.hpp"

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "model/exploration/exploration_model.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/util/hana_diff.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::conformance {

using namespace exploration;
using json_io::Json;

void write_counterexample(const std::string& path, const ExplorationCase& c, const Divergence& d) {
  Scenario s = c.scenario;
  s.max_steps = d.step;   // the trace ends where the engines part
  Json header = trace_header(s);
  header["impl_options"] = {{"grouped", c.grouped}};
  header["divergence"] = {{"step", d.step}, {"path", d.path}, {"model", d.model}, {"impl", d.impl},
                          {"spec_violation", d.spec_violation}, {"text", d.describe()}};
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "cannot write the counterexample trace");
    out << header.dump() << '\n';
    model::ExplorationModel m(s);
    out << trace_line(m.record()) << '\n';
    while (m.steps() < d.step) {
      m.step();
      out << trace_line(m.record()) << '\n';
    }
    if (!out) throw InputError(path, "writing the counterexample trace failed");
  }
  std::filesystem::rename(tmp, path);
}

namespace {

Json parse_line(const std::string& text, const std::string& where) {
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(where, "not valid JSON");
  }
}

struct TraceHeader {
  Scenario scenario;
  ExplorationOptions options;
  std::optional<std::string> recorded;
};

TraceHeader read_header(const Json& h, const std::string& where) {
  if (!h.is_object() || h.value("format", "") != "swarmcheck-trace")
    throw InputError(where, "expected a swarmcheck trace header ({\"format\": \"swarmcheck-trace\", ...})");
  if (h.value("system", "") != "exploration")
    throw InputError(where, "expected an exploration trace (\"system\": \"exploration\")");
  if (!h.contains("scenario")) throw InputError(where, "the header has no \"scenario\"");
  TraceHeader t;
  try {
    t.scenario = scenario_from_json(h["scenario"]);
  } catch (const InputError& e) {
    throw InputError(where, std::string("header: ") + e.what());
  }
  if (h.contains("impl_options") && h["impl_options"].value("grouped", false)) {
    t.options.parallel_min_robots = 1;
    t.options.parallel_min_bodies = 1;
  }
  if (h.contains("divergence")) t.recorded = h["divergence"].value("text", "");
  return t;
}

// Steps an engine to a given step and returns its record.
template <class Sim>
StepRecord record_at(Sim& sim, int64_t step) {
  while (sim.steps() < step && !sim.done()) sim.step();
  return sim.record();
}

template <class Sim>
ReplayResult replay_with(Sim& sim, std::ifstream& in, const std::string& path, ReplayResult result) {
  std::string line;
  int64_t lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty()) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    StepRecord expected;
    try {
      json_io::from_json(parse_line(line, where), "", expected);
    } catch (const InputError& e) {
      throw InputError(where, std::string("expected a step record: ") + e.what());
    }
    if (expected.step < sim.steps()) throw InputError(where, "records are not in increasing step order");
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
  return result;
}

}  // namespace

ReplayResult replay_trace(const std::string& path, Engine engine) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "cannot open the trace");
  std::string first;
  if (!std::getline(in, first)) throw InputError(path + ":1", "empty file: expected a trace header");
  const TraceHeader h = read_header(parse_line(first, path + ":1"), path + ":1");
  ReplayResult result;
  result.recorded = h.recorded;
  if (engine == Engine::model) {
    model::ExplorationModel m(h.scenario);
    return replay_with(m, in, path, result);
  }
  Exploration x(h.scenario, h.options);
  return replay_with(x, in, path, result);
}

}  // namespace swarmcheck::conformance
