#include "impl/dse/evaluate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "swarmcheck/exploration.hpp"

namespace swarmcheck::dse {
namespace {

using exploration::Scenario;
using json_io::Json;

// Running min, max and sum of one column's rows.
struct Accumulator {
  std::string name;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  double sum = 0;
  void add(double v) {
    min = std::min(min, v);
    max = std::max(max, v);
    sum += v;
  }
};

// Which odometers a run keeps: totals, and the robots asked for by name.
struct Odometers {
  bool distance_total = false, turning_total = false;
  std::vector<int32_t> distance_robots, turning_robots;
  bool any() const {
    return distance_total || turning_total || !distance_robots.empty() || !turning_robots.empty();
  }
};

Odometers odometers_of(const std::vector<Column>& columns) {
  Odometers o;
  for (const Column& c : columns) {
    if (c.series == Series::distance) {
      if (c.robot < 0) o.distance_total = true; else o.distance_robots.push_back(c.robot);
    } else if (c.series == Series::turning) {
      if (c.robot < 0) o.turning_total = true; else o.turning_robots.push_back(c.robot);
    }
  }
  return o;
}

}  // namespace

const Aggregate* RunOutputs::column(const std::string& name) const {
  for (const auto& [n, a] : columns)
    if (n == name) return &a;
  return nullptr;
}

std::vector<Column> needed_columns(const DseConfig& c) {
  std::vector<Column> out;
  for (const char* n : {"eP", "sTime", "visited", "planning_steps", "steps"}) out.push_back(*column_of(n));
  for (const Objective& o : c.objectives) {
    if (!follows_bodies(o.column.series)) continue;
    const bool seen = std::any_of(out.begin(), out.end(), [&](const Column& x) { return x.name == o.column.name; });
    if (!seen) out.push_back(o.column);
  }
  return out;
}

bool has_columns(const PointRuns& p, const std::vector<Column>& columns) {
  for (const RunOutputs& r : p.runs)
    for (const Column& c : columns)
      if (!r.column(c.name)) return false;
  return !p.runs.empty();
}

namespace {

// Follows one run row by row: the columns' accumulators and the odometers.
class Recorder {
 public:
  Recorder(const Scenario& s, const std::vector<Column>& columns, const Exploration& run)
      : columns_(columns), run_(run), odo_(odometers_of(columns)), n_(s.robots.size()),
        previous_(run.bodies().begin(), run.bodies().end()), distance_(n_, 0.0), turning_(n_, 0.0) {
    for (const Column& c : columns) {
      if (c.robot >= static_cast<int32_t>(n_))   // check_design_space refuses these first
        throw InputError(c.name, "the scenario has only " + std::to_string(n_) + " robots");
      acc_.push_back(Accumulator{c.name});
    }
  }

  // After each master step: the odometers advance by the bodies' moves.
  void advance() {
    if (!odo_.any()) return;
    const auto bodies = run_.bodies();
    for (std::size_t r = 0; r < n_; ++r) {
      const double d = std::hypot(bodies[r].x_m - previous_[r].x_m, bodies[r].y_m - previous_[r].y_m);
      const double t = std::fabs(bodies[r].theta_rad - previous_[r].theta_rad);
      distance_[r] += d;
      turning_[r] += t;
      distance_total_ += d;
      turning_total_ += t;
      previous_[r] = bodies[r];
    }
  }

  // One row: every column's value now.
  void record() {
    ++rows_;
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      const Column& c = columns_[k];
      const std::size_t robot = static_cast<std::size_t>(c.robot);
      switch (c.series) {
        case Series::eP: acc_[k].add(run_.eP()); break;
        case Series::sTime: acc_[k].add(run_.sTime()); break;
        case Series::visited: acc_[k].add(static_cast<double>(run_.visited())); break;
        case Series::planning_steps: acc_[k].add(static_cast<double>(run_.planning_steps())); break;
        case Series::steps: acc_[k].add(static_cast<double>(run_.steps())); break;
        case Series::distance: acc_[k].add(c.robot < 0 ? distance_total_ : distance_[robot]); break;
        case Series::turning: acc_[k].add(c.robot < 0 ? turning_total_ : turning_[robot]); break;
        case Series::completion_step: break;   // one value, taken at the end
      }
    }
  }

  std::vector<std::pair<std::string, Aggregate>> aggregates() const {
    std::vector<std::pair<std::string, Aggregate>> out;
    for (std::size_t k = 0; k < columns_.size(); ++k)
      if (columns_[k].series != Series::completion_step)
        out.emplace_back(acc_[k].name, Aggregate{acc_[k].min, acc_[k].max, acc_[k].sum / static_cast<double>(rows_)});
    return out;
  }

 private:
  const std::vector<Column>& columns_;
  const Exploration& run_;
  Odometers odo_;
  std::size_t n_;
  std::vector<exploration::BodyState> previous_;
  std::vector<double> distance_, turning_;
  double distance_total_ = 0, turning_total_ = 0;
  std::vector<Accumulator> acc_;
  int64_t rows_ = 0;
};

}  // namespace

RunOutputs run_scenario(const Scenario& s, const std::vector<Column>& columns) {
  // One thread per run: the DSE runs points in parallel instead.
  ExplorationOptions one_thread;
  one_thread.threads = 1;
  Exploration run(s, one_thread);
  Recorder rec(s, columns, run);
  rec.record();   // step 0, the initial state
  while (!run.done()) {
    run.step();
    rec.advance();
    rec.record();
  }
  RunOutputs out;
  out.seed = s.seed;
  out.steps = run.steps();
  out.completion_step = run.completion_step();
  out.columns = rec.aggregates();
  return out;
}

PointRuns evaluate_point(const DesignSpace& space, const Genome& g, const std::vector<Column>& columns) {
  PointRuns p;
  p.key = space.point_key(g);
  const int32_t n = space.replicates(g);
  for (int32_t r = 0; r < n; ++r) p.runs.push_back(run_scenario(space.scenario(g, r), columns));
  return p;
}

Json to_json(const PointRuns& p) {
  Json runs = Json::array();
  for (const RunOutputs& r : p.runs) {
    Json cols = Json::object();
    for (const auto& [name, a] : r.columns) cols[name] = Json::array({a.min, a.max, a.mean});
    runs.push_back(Json{{"seed", r.seed}, {"steps", r.steps},
                        {"completion_step", r.completion_step ? Json(*r.completion_step) : Json(nullptr)},
                        {"columns", std::move(cols)}});
  }
  return Json{{"key", p.key}, {"runs", std::move(runs)}};
}

PointRuns point_runs_from_json(const Json& j) {
  try {
    PointRuns p;
    p.key = j.at("key").get<std::string>();
    for (const Json& r : j.at("runs")) {
      RunOutputs o;
      o.seed = r.at("seed").get<uint64_t>();
      o.steps = r.at("steps").get<int64_t>();
      if (!r.at("completion_step").is_null()) o.completion_step = r.at("completion_step").get<int64_t>();
      for (auto it = r.at("columns").begin(); it != r.at("columns").end(); ++it) {
        const Json& a = it.value();
        o.columns.emplace_back(it.key(), Aggregate{a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()});
      }
      p.runs.push_back(std::move(o));
    }
    return p;
  } catch (const nlohmann::json::exception& e) {
    throw InputError("point record", std::string("malformed: ") + e.what());
  }
}

}  // namespace swarmcheck::dse
