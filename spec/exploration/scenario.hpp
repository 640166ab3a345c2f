#pragma once
// The built-in default scenario, scenario files, and their validation.
//
// Keys of a scenario file, exactly: map_size, cell_size (default 1), robots ([x, y] metres),
// obstacles ([i, j] cells), params (the thesis's names; each defaults to the built-in value),
// rule, mode, seed, max_steps. map_size and robots are required; obstacles default to none;
// the rest default to the built-in scenario's values. Every problem is an InputError naming the JSON path.
#include <optional>
#include <string>
#include <utility>

#include "spec/exploration/types.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

// Limits on everything: inputs beyond these are refused, not attempted.
inline constexpr int32_t kMapSizeMax = 65536;
inline constexpr int32_t kRangeMax = 1 << 20;
inline constexpr double kDepositMax = 1e12;      // max_ph + epsilon / a2
inline constexpr double kCosimStepMax_s = 0.5;   // the controllers are checked to arrive up to this step
inline constexpr int64_t kStepsMax = (int64_t{1} << 31) - 1;   // ~6.8 simulated years at 0.1 s
inline constexpr int64_t kRobotsMax = int64_t{1} << 30;

Params default_params();

// The thesis set-up: map 10, four robots at the corner cells, the 2x2 obstacle block at
// (4,4),(4,5),(5,4),(5,5), a1 = a2 = 0.5, epsilon 0.5, max_ph 2, eta 0.9, phi = lambda = 1,
// s_range 1; the deterministic rule set, cosim mode, seed 1.
Scenario default_scenario();

// Throws InputError("<path>", what was expected) on the first problem, checked in key order.
void validate(const Scenario& s);
// The intocps body's parameters (body_choice.cpp): finite, physical, and no mode faster than RK4
// at 1 ms can follow. Throws InputError("body.parameters.<name>", ...).
void validate_intocps_params(const IntocpsBodyParams& p);

// A run's command-line overrides of a scenario's keys (each if given).
struct ScenarioOverrides {
  std::optional<Mode> mode;
  std::optional<RuleSet> rule;
  std::optional<ControllerKind> controller;
  std::optional<BodyKind> body;   // the intocps body keeps the scenario's parameters
  std::optional<uint64_t> seed;
  std::optional<int64_t> max_steps;
};

// A scenario validate() accepted, held so that nothing changes it: what takes one (Exploration's
// constructor) need not validate it again, which costs a sort of the robots' cells.
class ValidScenario {
 public:
  explicit ValidScenario(Scenario s) : s_(std::move(s)) { validate(s_); }   // throws as validate()
  const Scenario& get() const { return s_; }
  operator const Scenario&() const { return s_; }
  // The scenario, to change (and validate again).
  Scenario release() && { return std::move(s_); }

 private:
  struct Checked {};
  ValidScenario(Scenario s, Checked) : s_(std::move(s)) {}
  friend ValidScenario with_overrides(ValidScenario s, const ScenarioOverrides& o);
  Scenario s_;
};

// `s` with the overrides, validated again (throws as validate()): every check but the cells',
// which read only the map, the robots and the obstacles, none of which an override changes.
ValidScenario with_overrides(ValidScenario s, const ScenarioOverrides& o);

// Parses and validates a scenario file's text; `file` prefixes every message. Big robot and
// obstacle lists are read without a JSON DOM (spec/util/json_pair_lists.hpp); the result and
// every message are parse_scenario_dom's.
ValidScenario parse_valid_scenario(const std::string& text, const std::string& file);
Scenario parse_scenario(const std::string& text, const std::string& file);

// The same through a whole JSON DOM: the reference the fast path is tested against.
Scenario parse_scenario_dom(const std::string& text, const std::string& file);

// A scenario from parsed JSON (as parse_scenario, without the file name in the messages).
Scenario scenario_from_json(const json_io::Json& j);

// Reads, parses and validates a file.
ValidScenario load_valid_scenario(const std::string& path);
Scenario load_scenario(const std::string& path);

int64_t free_cell_count(const Scenario& s);

}  // namespace swarmcheck::exploration
