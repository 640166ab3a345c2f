#pragma once
// The one table from the names a DSE configuration uses to what they mean: the thesis's
// Environment FMU variables in INTO-CPS's form (`{Environment}.EnvironmentInstance.ertu_perc`) or
// plainly (`ertu_perc`), and swarmcheck's own sweepables, to scenario keys; and the output
// columns a run offers to objectives. The README's parameter table is this table.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "impl/dse/expression.hpp"

namespace swarmcheck::dse {

// What a swept parameter sets in the base scenario.
enum class Knob : uint8_t {
  s_range, a1, a2, epsilon, max_ph, ertu, eta, phi, lambda, step_size,   // params.*
  map_size, cell_size, robot_count, obstacle_count, obstacle_density,
  rule, mode, controller, body, seed, max_steps, replicates
};

struct KnobInfo {
  Knob knob;
  std::string_view name;          // canonical (the scenario key or swarmcheck's name)
  std::string_view aliases;       // other accepted plain names, space separated
  std::string_view scenario_key;  // what it sets
  ValueType type;                 // number (integers are checked where needed) or text
  bool integer;
  std::string_view meaning;
};

std::span<const KnobInfo> knob_table();
const KnobInfo& knob_info(Knob k);

// Strips INTO-CPS's `{Environment}.<instance>.` prefix; a name with another FMU's prefix is
// returned unchanged (and is then unknown).
std::string plain_name(const std::string& name);

// A parameter name (either form) to its knob; nullopt when unknown.
std::optional<Knob> knob_of(const std::string& name);
// "ertu_perc, s_range, ..." for messages.
std::string known_parameter_names();

// Output columns of a run (one value per master step, step 0 included), for
// objectiveDefinitions.internalFunctions' columnID.
enum class Series : uint8_t { eP, sTime, visited, planning_steps, steps, completion_step, distance, turning };

struct Column {
  Series series = Series::eP;
  int32_t robot = -1;   // 0-based robot for distance_<k> / turning_<k> (k = robot + 1); -1: total
  std::string name;     // canonical: "eP", "distance", "distance_3", ...
};

// A column name (either form) to its column; nullopt when unknown.
std::optional<Column> column_of(const std::string& name);
std::string known_column_names();
// distance and turning follow the bodies every step; the rest are the Environment's outputs.
inline bool follows_bodies(Series s) { return s == Series::distance || s == Series::turning; }

}  // namespace swarmcheck::dse
