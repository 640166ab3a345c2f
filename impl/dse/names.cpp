#include "impl/dse/names.hpp"

#include <array>
#include <charconv>
#include <sstream>

namespace swarmcheck::dse {
namespace {

using VT = ValueType;

constexpr std::array<KnobInfo, 22> kKnobs{{
    {Knob::s_range, "s_range", "", "params.s_range", VT::number, true, "sensing and spraying range, cells"},
    {Knob::a1, "a1", "", "params.a1", VT::number, false, "deposit decay length, cells"},
    {Knob::a2, "a2", "", "params.a2", VT::number, false, "divisor of the uniform deposit term"},
    {Knob::epsilon, "epsilon", "", "params.epsilon", VT::number, false, "uniform deposit numerator"},
    {Knob::max_ph, "max_ph", "", "params.max_ph", VT::number, false, "peak deposit"},
    {Knob::ertu, "ertu_perc", "ertu", "params.ertu", VT::number, false, "evaporation rate, 1/s"},
    {Knob::eta, "eta", "", "params.eta", VT::number, false, "heuristic factor"},
    {Knob::phi, "phi", "", "params.phi", VT::number, false, "pheromone exponent"},
    {Knob::lambda, "lambda", "", "params.lambda", VT::number, false, "heuristic exponent"},
    {Knob::step_size, "step_size", "", "params.step_size", VT::number, false, "master step, s"},
    {Knob::map_size, "mapSize", "map_size", "map_size", VT::number, true, "map side, cells"},
    {Knob::cell_size, "cellSize", "cell_size", "cell_size", VT::number, false, "cell side, m"},
    {Knob::robot_count, "nRobots", "n_robots", "robots", VT::number, true,
     "robot count; robots placed on distinct free cells drawn from the run's seed"},
    {Knob::obstacle_count, "nObstacles", "n_obstacles", "obstacles", VT::number, true,
     "obstacle count; cells drawn from the run's seed"},
    {Knob::obstacle_density, "obstacleDensity", "obstacle_density", "obstacles", VT::number, false,
     "share of the map's cells made obstacles (rounded), drawn from the run's seed"},
    {Knob::rule, "rule", "", "rule", VT::text, false, "thesis | deterministic | stochastic"},
    {Knob::mode, "mode", "", "mode", VT::text, false, "abstract | cosim"},
    {Knob::controller, "controller", "", "controller", VT::text, false, "swarmcheck | thesis (cosim mode)"},
    {Knob::body, "body", "", "body", VT::text, false,
     "kinematic | intocps (cosim mode; an intocps body keeps the base scenario's parameters)"},
    {Knob::seed, "seed", "", "seed", VT::number, true, "the point's one seed"},
    {Knob::max_steps, "max_steps", "maxSteps", "max_steps", VT::number, true, "master steps at most"},
    {Knob::replicates, "replicates", "", "(runs per point)", VT::number, true,
     "runs per point with seeds derived from the seed; objectives as mean and 95 % interval"},
}};

constexpr std::string_view kEnvironmentPrefix = "{Environment}.";

bool has_word(std::string_view list, std::string_view word) {
  std::size_t k = 0;
  while (k < list.size()) {
    const std::size_t e = std::min(list.find(' ', k), list.size());
    if (list.substr(k, e - k) == word) return true;
    k = e + 1;
  }
  return false;
}

struct SeriesName {
  Series series;
  std::string_view name;
  std::string_view aliases;
};
constexpr std::array<SeriesName, 8> kSeries{{
    {Series::eP, "eP", "explorationPercentage"},
    {Series::sTime, "sTime", "simulationTime"},
    {Series::visited, "visited", "vCells"},
    {Series::planning_steps, "planning_steps", "planningSteps"},
    {Series::steps, "steps", "stepCount"},
    {Series::completion_step, "completion_step", "completionStep"},
    {Series::distance, "distance", "travelled"},
    {Series::turning, "turning", ""},
}};

}  // namespace

std::span<const KnobInfo> knob_table() { return kKnobs; }

const KnobInfo& knob_info(Knob k) {
  for (const KnobInfo& i : kKnobs)
    if (i.knob == k) return i;
  return kKnobs[0];
}

std::string plain_name(const std::string& name) {
  if (name.rfind(kEnvironmentPrefix, 0) != 0) return name;
  const std::size_t dot = name.find('.', kEnvironmentPrefix.size());
  if (dot == std::string::npos) return name;
  return name.substr(dot + 1);
}

std::optional<Knob> knob_of(const std::string& name) {
  const std::string plain = plain_name(name);
  for (const KnobInfo& i : kKnobs)
    if (plain == i.name || has_word(i.aliases, plain)) return i.knob;
  return std::nullopt;
}

std::string known_parameter_names() {
  std::string out;
  for (const KnobInfo& i : kKnobs) out += (out.empty() ? "" : ", ") + std::string(i.name);
  return out;
}

std::optional<Column> column_of(const std::string& name) {
  const std::string plain = plain_name(name);
  for (const SeriesName& s : kSeries)
    if (plain == s.name || has_word(s.aliases, plain)) return Column{s.series, -1, std::string(s.name)};
  // distance_<k> / turning_<k>, k >= 1 (the thesis numbers robots from 1: x_1, y_1, ...)
  for (const std::string_view base : {std::string_view("distance"), std::string_view("turning")}) {
    if (plain.size() <= base.size() + 1 || plain.compare(0, base.size(), base) != 0 || plain[base.size()] != '_')
      continue;
    int32_t k = 0;
    const char* first = plain.data() + base.size() + 1;
    const char* last = plain.data() + plain.size();
    const auto r = std::from_chars(first, last, k);
    if (r.ec != std::errc() || r.ptr != last || k < 1 || *first == '0') continue;
    const Series series = base == "distance" ? Series::distance : Series::turning;
    return Column{series, k - 1, plain};
  }
  return std::nullopt;
}

std::string known_column_names() {
  std::string out;
  for (const SeriesName& s : kSeries) out += (out.empty() ? "" : ", ") + std::string(s.name);
  return out + ", distance_<k>, turning_<k> (robot k, from 1)";
}

}  // namespace swarmcheck::dse
