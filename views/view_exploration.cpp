// The exploration trace view and the conformance counterexample view (views/view.hpp).
#include <algorithm>
#include <fmt/format.h>

#include "conformance/exploration/engine.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace_field.hpp"
#include "spec/util/input_error.hpp"
#include "views/run_recorder.hpp"
#include "views/svg.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {
namespace {

using namespace swarmcheck::exploration;
using json_io::Json;

Json rgb(Rgb c) { return Json::array({c[0], c[1], c[2]}); }

Json palette() {
  Json heat = Json::array();
  for (const Rgb& c : kHeatStops) heat.push_back(rgb(c));
  Json robots = Json::array();
  for (const Rgb& c : kRobotColours) robots.push_back(rgb(c));
  return {{"heat", heat}, {"obstacle", rgb(kObstacle)}, {"unvisited", rgb(kUnvisitedDot)},
          {"grid", rgb(kGridLine)}, {"robots", robots}};
}

struct Trace {
  Json header;
  Scenario scenario;
  std::vector<StepRecord> records;
  std::vector<Json> fields;   // the field lines, checked
};

Trace read_trace(const std::string& text, const std::string& path) {
  const std::vector<JsonLine> lines = json_lines(text, path);
  Trace t;
  t.header = lines.front().json;
  const std::string where = path + ":" + std::to_string(lines.front().number);
  if (!t.header.contains("scenario")) throw InputError(where, "the header has no \"scenario\"");
  try {
    t.scenario = scenario_from_json(t.header["scenario"]);
  } catch (const InputError& e) {
    throw InputError(where, std::string("header: ") + e.what());
  }
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::string at = path + ":" + std::to_string(lines[k].number);
    const Json& j = lines[k].json;
    if (json_io::string_member(j, "type") == "field") {
      const DecodedField f = decode_field_record(j, at);
      if (f.map_size != t.scenario.map_size)
        throw InputError(at, fmt::format("field of map_size {}, but the scenario's map is {}", f.map_size, t.scenario.map_size));
      t.fields.push_back(j);
      continue;
    }
    StepRecord r;
    try {
      json_io::from_json(j, "", r);
    } catch (const InputError& e) {
      throw InputError(at, std::string("expected a step record: ") + e.what());
    }
    if (r.robots.size() != t.scenario.robots.size())
      throw InputError(at, fmt::format("expected {} robots (the scenario's), got {}", t.scenario.robots.size(), r.robots.size()));
    if (!t.records.empty() && r.step <= t.records.back().step)
      throw InputError(at, "records are not in increasing step order");
    t.records.push_back(std::move(r));
  }
  if (t.records.empty()) throw InputError(path, "the trace has a header but no step record");
  return t;
}

// Which records to keep: at most max evenly spaced, always the first, the last and those at a
// field record's step.
std::vector<std::size_t> kept(const Trace& t, int64_t max) {
  std::vector<std::size_t> keep;
  const std::size_t n = t.records.size();
  std::vector<int64_t> field_steps;
  for (const Json& f : t.fields) field_steps.push_back(f["step"].get<int64_t>());
  const double stride = n <= static_cast<std::size_t>(max) ? 1.0 : static_cast<double>(n - 1) / static_cast<double>(max - 1);
  double next = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const bool field = std::binary_search(field_steps.begin(), field_steps.end(), t.records[k].step);
    if (k + 1 == n || static_cast<double>(k) >= next || field) {
      keep.push_back(k);
      while (next <= static_cast<double>(k)) next += stride;
    }
  }
  return keep;
}

Json compact_records(const Trace& t, const std::vector<std::size_t>& keep) {
  Json step = Json::array(), eP = Json::array(), sTime = Json::array(), flag = Json::array(),
       env_od = Json::array(), planning = Json::array(), visited = Json::array();
  Json robots = Json::array();
  const std::size_t nr = t.scenario.robots.size();
  std::vector<std::array<Json, 9>> cols(nr);
  for (auto& c : cols) c.fill(Json::array());
  for (const std::size_t k : keep) {
    const StepRecord& r = t.records[k];
    step.push_back(r.step);
    eP.push_back(r.eP);
    sTime.push_back(r.sTime);
    flag.push_back(r.handshake.flag);
    env_od.push_back(r.handshake.on_destination_output);
    planning.push_back(r.planning_steps);
    visited.push_back(r.visited);
    for (std::size_t q = 0; q < nr; ++q) {
      const RobotRecord& x = r.robots[q];
      const double vals[9] = {x.body.x_m, x.body.y_m, x.body.theta_rad, double(x.cell[0]), double(x.cell[1]),
                              x.waypoint[0], x.waypoint[1], double(x.controller.on_destination_output),
                              double(x.controller.maneuver)};
      for (int c = 0; c < 9; ++c) cols[q][c].push_back(vals[c]);
    }
  }
  const char* names[9] = {"x", "y", "theta", "ci", "cj", "wx", "wy", "onDest", "maneuver"};
  for (std::size_t q = 0; q < nr; ++q) {
    Json o = Json::object();
    for (int c = 0; c < 9; ++c) o[names[c]] = cols[q][c];
    robots.push_back(o);
  }
  return {{"step", step}, {"eP", eP}, {"sTime", sTime}, {"flag", flag}, {"envOnDest", env_od},
          {"planning", planning}, {"visited", visited}, {"robots", robots}};
}

// The digest as text: a u64 does not fit a JavaScript number.
Json record_json(const StepRecord& r) {
  Json j = json_io::to_json(r);
  j["pheromone_digest"] = fmt::format("{:016x}", r.pheromone_digest);
  return j;
}

Json field_json(const FieldSnapshot& f) {
  Json j = field_record(f);
  j["digest"] = fmt::format("{:016x}", j["digest"].get<uint64_t>());
  return j;
}

// Both engines re-run to the divergence step: their records and grids, side by side.
void add_counterexample(Json& data, const Trace& t) {
  namespace cx = conformance::exploration;
  const Json& d = t.header["divergence"];
  data["divergence"] = d;
  ExplorationOptions options;
  if (t.header.contains("impl_options") && t.header["impl_options"].is_object() &&
      t.header["impl_options"].value("grouped", json_io::Json(false)) == json_io::Json(true)) {
    options = conformance::exploration::grouped_options();
  }
  const int64_t step = t.records.back().step;
  Json sides = Json::object();
  for (const auto& [name, engine] : {std::pair{"model", cx::Engine::model}, std::pair{"impl", cx::Engine::impl}}) {
    const auto sim = cx::make_simulation(engine, t.scenario, options);
    while (sim->steps() < step && !sim->done()) sim->step();
    sides[name] = {{"record", record_json(sim->record())}, {"field", field_json(field_snapshot(*sim, t.scenario))}};
  }
  data["sides"] = sides;
  data["recorded"] = record_json(t.records.back());
}

}  // namespace

Page exploration_page(const std::string& text, const std::string& path, const ViewOptions& o) {
  if (o.max_records < 2) throw InputError("--max-records", "expected an integer >= 2");
  const Trace t = read_trace(text, path);
  const bool counterexample = t.header.contains("divergence");
  if (counterexample && !t.header["divergence"].is_object())
    throw InputError(path + ":1", "\"divergence\" must be an object");
  const std::vector<std::size_t> keep = kept(t, o.max_records);
  Json header = t.header;
  header.erase("scenario");
  Json data = {{"kind", counterexample ? "counterexample" : "exploration"},
               {"file", path},
               {"scenario", json_io::to_json(t.scenario)},
               {"header", header},
               {"palette", palette()},
               {"records_total", t.records.size()},
               {"records", compact_records(t, keep)}};
  Json fields = Json::array();
  for (Json f : t.fields) {
    f["digest"] = fmt::format("{:016x}", f["digest"].get<uint64_t>());
    fields.push_back(f);
  }
  data["fields"] = fields;
  // The intocps body reports a point `axle_offset` ahead of the axle it turns about: the view
  // draws the body at the axle and the reported point in front of it.
  if (t.scenario.mode == Mode::cosim && t.scenario.body.kind == BodyKind::intocps)
    data["axle_offset"] = t.scenario.body.intocps.axle_offset;
  if (counterexample) add_counterexample(data, t);
  const std::string title = (counterexample ? "swarmcheck counterexample: " : "swarmcheck trace: ") + path;
  return Page{title, data};
}

json_io::Json exploration_palette() { return palette(); }

}  // namespace swarmcheck::views
