#include "spec/exploration/scenario.hpp"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "spec/exploration/domains.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/util/demand.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/json_pair_lists.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::exploration {
namespace {

// The shortest text that reads back as v.
std::string fmt_num(double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, res.ptr);
}

void require(bool ok, const std::string& path, const std::string& expected, double got) {
  if (!ok) throw InputError(path, "expected " + expected + ", got " + fmt_num(got));
}

// A numeric key's current value, by its JSON path in kScenarioDomains.
double value_at(const Scenario& s, std::string_view path) {
  double out = 0.0;
  bool found = false;
  auto pick = [&](const auto& object, std::string_view name) {
    boost::hana::for_each(boost::hana::accessors<std::decay_t<decltype(object)>>(), [&](auto pair) {
      using Member = std::decay_t<decltype(boost::hana::second(pair)(object))>;
      if constexpr (std::is_arithmetic_v<Member>) {
        if (name == boost::hana::to<const char*>(boost::hana::first(pair))) {
          out = static_cast<double>(boost::hana::second(pair)(object));
          found = true;
        }
      }
    });
  };
  if (path.starts_with("params.")) pick(s.params, path.substr(7));
  else pick(s, path);
  SWARM_DEMAND(found);
  return out;
}

void validate_domains(const Scenario& s, DomainStage stage) {
  for (const Domain& d : kScenarioDomains) {
    if (d.stage != stage) continue;
    const double v = value_at(s, d.path);
    require(in_domain(d, v), std::string(d.path), std::string(d.expected), v);
  }
}

void validate_cross_params(const Params& p, Mode mode) {
  if (mode == Mode::cosim)
    require(p.step_size <= kCosimStepMax_s, "params.step_size",
            "at most " + fmt_num(kCosimStepMax_s) +
                " s in cosim mode (the controllers are checked to arrive on both bodies up to this step)",
            p.step_size);
  const double deposit = p.max_ph + p.epsilon / p.a2;
  require(deposit <= kDepositMax, "params",
          "max_ph + epsilon / a2 at most " + fmt_num(kDepositMax) + " (pheromone must stay finite)",
          deposit);
}

std::string cell_text(CellIndex c) {
  return "[" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + "]";
}

// A cell and an index packed in one integer, cell in the high half (maps have at most 2^32 cells,
// lists at most 2^32 entries): sorting them sorts by cell, then index.
uint64_t packed(CellIndex c, int32_t map_size, std::size_t k) {
  return ((static_cast<uint64_t>(c[0]) * static_cast<uint64_t>(map_size) + static_cast<uint64_t>(c[1])) << 32) |
         static_cast<uint64_t>(k);
}
std::size_t index_of(uint64_t p) { return static_cast<std::size_t>(p & 0xffffffffU); }
uint64_t cell_of_packed(uint64_t p) { return p >> 32; }

// The smallest index that repeats an earlier index's cell (n if none), and that earlier index;
// `sorted` is packed cells, sorted.
std::pair<std::size_t, std::size_t> first_repeat(const std::vector<uint64_t>& sorted, std::size_t n) {
  std::pair<std::size_t, std::size_t> best{n, n};
  for (std::size_t k = 1; k < sorted.size(); ++k)
    if (cell_of_packed(sorted[k]) == cell_of_packed(sorted[k - 1]) && index_of(sorted[k]) < best.first)
      best = {index_of(sorted[k]), index_of(sorted[k - 1])};
  return best;
}

// Linear-logarithmic in the cells (a scenario of 10^6 robots validates in well under a second):
// every check is made for all entries, and the error reported is the one a pass in index order
// would meet first.
void validate_cells(const Scenario& s) {
  const std::size_t n_obstacles = s.obstacles.size();
  std::size_t bad_obstacle = n_obstacles;
  std::vector<uint64_t> obstacle_cells;
  obstacle_cells.reserve(n_obstacles);
  for (std::size_t k = 0; k < n_obstacles; ++k) {
    if (!in_map(s.obstacles[k], s.map_size)) {
      bad_obstacle = k;
      break;
    }
    obstacle_cells.push_back(packed(s.obstacles[k], s.map_size, k));
  }
  std::sort(obstacle_cells.begin(), obstacle_cells.end());
  const auto [repeat, repeated] = first_repeat(obstacle_cells, n_obstacles);
  if (repeat < bad_obstacle)
    throw InputError("obstacles[" + std::to_string(repeat) + "]", "cell " + cell_text(s.obstacles[repeat]) +
                                                                      " repeats obstacles[" + std::to_string(repeated) + "]");
  if (bad_obstacle < n_obstacles)
    throw InputError("obstacles[" + std::to_string(bad_obstacle) + "]",
                     "expected a cell [i, j] with 0 <= i, j < " + std::to_string(s.map_size) + ", got " +
                         cell_text(s.obstacles[bad_obstacle]));
  if (s.robots.empty()) throw InputError("robots", "expected at least one robot");
  if (static_cast<int64_t>(s.robots.size()) > kRobotsMax)
    throw InputError("robots", "expected at most 2^30 robots, got " + std::to_string(s.robots.size()));
  const double side_m = s.map_size * s.cell_size;
  const std::size_t n = s.robots.size();
  // Robot k fails on its position, else on an obstacle's cell, else on an earlier robot's cell.
  std::size_t bad_position = n, on_obstacle = n;
  std::vector<uint64_t> robot_cells;
  robot_cells.reserve(n);
  // The first obstacle entry of a cell at or after the cell's packed key with index 0.
  const auto obstacle_entry = [&](CellIndex c) {
    return std::lower_bound(obstacle_cells.begin(), obstacle_cells.end(), packed(c, s.map_size, 0));
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Point_m p = s.robots[k];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && p[0] >= 0 && p[1] >= 0 && p[0] < side_m && p[1] < side_m)) {
      bad_position = k;
      break;
    }
    const CellIndex c = cell_of(p, s.cell_size);
    if (on_obstacle == n && !obstacle_cells.empty()) {
      const auto at = obstacle_entry(c);
      if (at != obstacle_cells.end() && cell_of_packed(*at) == cell_of_packed(packed(c, s.map_size, 0))) on_obstacle = k;
    }
    robot_cells.push_back(packed(c, s.map_size, k));
  }
  std::sort(robot_cells.begin(), robot_cells.end());
  const auto [taken, taker] = first_repeat(robot_cells, n);
  const std::size_t first = std::min({bad_position, on_obstacle, taken});
  if (first == n) return;
  const std::string path = "robots[" + std::to_string(first) + "]";
  const Point_m p = s.robots[first];
  if (first == bad_position)
    throw InputError(path, "expected a position [x, y] in metres with 0 <= x, y < " + fmt_num(side_m) + ", got [" +
                               fmt_num(p[0]) + ", " + fmt_num(p[1]) + "]");
  const CellIndex c = cell_of(p, s.cell_size);
  if (first == on_obstacle) {
    throw InputError(path, "starts in cell " + cell_text(c) + ", which is obstacles[" +
                               std::to_string(index_of(*obstacle_entry(c))) + "]");
  }
  throw InputError(path, "starts in cell " + cell_text(c) + ", already taken by robots[" + std::to_string(taker) + "]");
}

}  // namespace

Params default_params() {
  Params p;
  p.s_range = 1;
  p.a1 = 0.5;
  p.a2 = 0.5;
  p.epsilon = 0.5;
  p.max_ph = 2.0;
  p.ertu = 0.1;
  p.eta = 0.9;
  p.phi = 1.0;
  p.lambda = 1.0;
  p.step_size = 0.1;
  return p;
}

Scenario default_scenario() {
  Scenario s;
  s.map_size = 10;
  s.cell_size = 1.0;
  s.robots = {{0.5, 0.5}, {9.5, 0.5}, {0.5, 9.5}, {9.5, 9.5}};
  s.obstacles = {{4, 4}, {4, 5}, {5, 4}, {5, 5}};
  s.params = default_params();
  s.rule = RuleSet::deterministic;
  s.mode = Mode::cosim;
  s.seed = 1;
  s.max_steps = 100000;
  s.controller = ControllerKind::swarmcheck;
  s.body = BodyChoice{};
  return s;
}

namespace {
// validate's checks in order, the cells' only if asked for.
void validate_checks(const Scenario& s, bool cells) {
  validate_domains(s, DomainStage::before_cells);
  if (cells) validate_cells(s);
  validate_domains(s, DomainStage::params);
  validate_cross_params(s.params, s.mode);
  validate_domains(s, DomainStage::after_params);
  validate_intocps_params(s.body.intocps);
}
}  // namespace

void validate(const Scenario& s) { validate_checks(s, true); }

ValidScenario with_overrides(ValidScenario v, const ScenarioOverrides& o) {
  Scenario s = std::move(v).release();
  if (o.mode) s.mode = *o.mode;
  if (o.rule) s.rule = *o.rule;
  if (o.controller) s.controller = *o.controller;
  if (o.body) s.body.kind = *o.body;
  if (o.seed) s.seed = *o.seed;
  if (o.max_steps) s.max_steps = *o.max_steps;
  // The cells passed before and nothing they read changed: the first failing check, in order, is
  // the same without them.
  validate_checks(s, false);
  return ValidScenario(std::move(s), ValidScenario::Checked{});
}

namespace {

// The members a scenario's JSON sets, over the defaults; not validated.
Scenario read_scenario_json(const json_io::Json& j) {
  Scenario s = default_scenario();
  s.obstacles.clear();   // a file without "obstacles" has none (the default's block is map-10 only)
  if (!j.is_object()) throw InputError("(top level)", "expected an object");
  if (!j.contains("map_size")) throw InputError("map_size", "missing (the map's side in cells)");
  if (!j.contains("robots")) throw InputError("robots", "missing (a list of [x, y] positions)");
  json_io::from_json(j, "", s);
  return s;
}

// The fast path (json_pair_lists.hpp): robots and obstacles read without a DOM, the rest of the
// text through the ordinary reader. Nothing when the text is not the plain case or the rest has
// any error: the whole text is then read the ordinary way, which reports it as it always has.
std::optional<Scenario> read_scenario_fast(const std::string& text, const std::string& file) {
  std::vector<Point_m> robots;
  std::vector<CellIndex> obstacles;
  json_io::PairList<double> robot_list{"robots", &robots};
  json_io::PairList<int32_t> obstacle_list{"obstacles", &obstacles};
  const std::optional<std::string> rest = json_io::extract_pair_lists(text, robot_list, obstacle_list);
  if (!rest) return std::nullopt;
  std::optional<Scenario> s;
  try {
    s = read_scenario_json(json_io::parse_json_text(*rest, file));
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (robot_list.found) s->robots = std::move(robots);
  if (obstacle_list.found) s->obstacles = std::move(obstacles);
  return s;
}

}  // namespace

ValidScenario parse_valid_scenario(const std::string& text, const std::string& file) {
  std::optional<Scenario> s = read_scenario_fast(text, file);
  if (!s) {
    const auto j = json_io::parse_json_text(text, file);   // syntax: file:line:col
    try {
      s = read_scenario_json(j);
    } catch (const InputError& e) {
      throw json_io::in_file(e, file);
    }
  }
  try {
    return ValidScenario(std::move(*s));
  } catch (const InputError& e) {
    throw json_io::in_file(e, file);
  }
}

Scenario parse_scenario(const std::string& text, const std::string& file) {
  return parse_valid_scenario(text, file).release();
}

Scenario parse_scenario_dom(const std::string& text, const std::string& file) {
  const auto j = json_io::parse_json_text(text, file);
  try {
    return scenario_from_json(j);
  } catch (const InputError& e) {
    throw json_io::in_file(e, file);
  }
}

Scenario scenario_from_json(const json_io::Json& j) {
  Scenario s = read_scenario_json(j);
  validate(s);
  return s;
}

ValidScenario load_valid_scenario(const std::string& path) {
  return parse_valid_scenario(io_input::read_input_file(path, "scenario file"), path);
}

Scenario load_scenario(const std::string& path) { return load_valid_scenario(path).release(); }

int64_t free_cell_count(const Scenario& s) {
  return int64_t{s.map_size} * s.map_size - static_cast<int64_t>(s.obstacles.size());
}

}  // namespace swarmcheck::exploration
