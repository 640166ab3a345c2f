#pragma once
// Rule sets of the Environment (DESIGN.md A2-A5, spec/SPEC.md section 3): each is ONE row of
// kRuleSets below. A row names the rule for every decision the Environment makes; the executable
// step (environment_step.hpp) reads these fields and nothing else, so model/ and impl/ never test
// which rule set is running. A new rule set is a new enumerator, its name and its row here (plus
// its tests): see spec/SPEC.md section 12 for the list of files it touches.
#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

enum class RuleSet { thesis, deterministic, stochastic };

// Which candidate is the best (choice.hpp).
enum class BestRule {
  thesis_normalised,   // probN / sum <= best value, starting from pow(1000, phi) eta^lambda / sum
  last_minimum,        // the last minimum of pow(tau, phi) in raster order
  uniform_minimum,     // uniform among the minima of pow(tau, phi) (keyed RNG, tie_break)
};

// The free candidate a blocked best falls back to (choice.hpp). None free: the robot stays.
enum class FallbackRule {
  first_free,      // the first free candidate in raster order
  uniform_free,    // uniform among the free candidates (keyed RNG, fallback)
};

// What a move to the fallback candidate does to the map.
enum class FallbackEffect {
  occupy_and_mark,   // like any move: the cell becomes occupied and visited
  move_copy,         // the thesis moved a copy of the cell: position and waypoint only
};

// Around which cell a planning robot deposits.
enum class DepositCentre { robot_cell, best };

// How pheromone evaporates every step (decay.hpp).
enum class Evaporation {
  decay_function,     // tau = value * F(t - written): a lazy implementation is bit-identical
  literal_per_step,   // the thesis's in-place ph -= ertu dt ph; clamp at 0, on every cell
};

struct RuleDescriptor {
  RuleSet id;
  std::string_view name;   // the scenario file's and the command line's spelling
  BestRule best;
  FallbackRule fallback;
  FallbackEffect fallback_effect;
  DepositCentre deposit_centre;
  Evaporation evaporation;
  // Occupancy (one robot per cell, none on an obstacle) and visited <= free cells hold after
  // every step; the thesis's copy-moves break them, on purpose.
  bool keeps_occupancy_invariants;
};

inline constexpr std::array<RuleDescriptor, 3> kRuleSets{{
    {RuleSet::thesis, "thesis", BestRule::thesis_normalised, FallbackRule::first_free,
     FallbackEffect::move_copy, DepositCentre::best,
     Evaporation::literal_per_step, false},
    {RuleSet::deterministic, "deterministic", BestRule::last_minimum, FallbackRule::first_free,
     FallbackEffect::occupy_and_mark, DepositCentre::robot_cell,
     Evaporation::decay_function, true},
    {RuleSet::stochastic, "stochastic", BestRule::uniform_minimum, FallbackRule::uniform_free,
     FallbackEffect::occupy_and_mark, DepositCentre::robot_cell,
     Evaporation::decay_function, true},
}};

// The row of a rule set (rows are in enumerator order; checked at compile time below).
constexpr const RuleDescriptor& rules_of(RuleSet r) { return kRuleSets[static_cast<std::size_t>(r)]; }

constexpr bool rows_in_enumerator_order() {
  for (std::size_t k = 0; k < kRuleSets.size(); ++k)
    if (static_cast<std::size_t>(kRuleSets[k].id) != k) return false;
  return true;
}
static_assert(rows_in_enumerator_order(), "kRuleSets rows must follow the RuleSet enumerators");

// Every rule set, in table order (generators draw from this, so a new row is generated at once).
constexpr std::array<RuleSet, kRuleSets.size()> all_rule_sets() {
  std::array<RuleSet, kRuleSets.size()> out{};
  for (std::size_t k = 0; k < kRuleSets.size(); ++k) out[k] = kRuleSets[k].id;
  return out;
}

}  // namespace swarmcheck::exploration

namespace swarmcheck::json_io {
// Scenario files and the command line spell rule sets as the table does.
template <>
struct EnumNames<exploration::RuleSet> {
  static constexpr auto names = [] {
    std::array<std::pair<exploration::RuleSet, std::string_view>, exploration::kRuleSets.size()> out{};
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = {exploration::kRuleSets[k].id, exploration::kRuleSets[k].name};
    return out;
  }();
};
}  // namespace swarmcheck::json_io
