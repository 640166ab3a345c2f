#pragma once
// The domain of every numeric scenario key, declared once. validate() (scenario.cpp) checks a
// scenario against this table, and the JSON Schema that the editor page validates with
// (views/schema.cpp) is generated from it and from the Hana declarations of types.hpp, so the
// CLI and the editor accept the same files and say the same thing about the others.
//
// The rules across keys (cells in the map, distinct cells, robots not on obstacles, the cosim
// step bound, the deposit bound) are named in kScenarioRules and written in both languages;
// tests/browser/validate_test.mjs checks that both give the same message on the same files.
#include <array>
#include <string_view>

#include "spec/exploration/scenario.hpp"

namespace swarmcheck::exploration {

enum class DomainStage { before_cells, params, after_params };

struct Domain {
  std::string_view path;        // JSON path, e.g. "map_size", "params.a1"
  DomainStage stage;            // when validate() checks it (the order of the messages)
  bool integer;                 // an integer key (else a number, which must be finite)
  bool has_min;
  double min;
  bool min_exclusive;           // > min rather than >= min
  bool has_max;
  double max;
  std::string_view expected;    // the message's "expected ..." text
};

inline constexpr std::array<Domain, 13> kScenarioDomains{{
    {"map_size", DomainStage::before_cells, true, true, 1, false, true, kMapSizeMax, "an integer in [1, 65536]"},
    // Bounded so that every position (map_size cells of cell_size) and every time (kStepsMax steps
    // of step_size) is a finite double: 1e308 was accepted and ran into traces of infinities.
    {"cell_size", DomainStage::before_cells, false, true, 0, true, true, 1e6, "a number in (0, 1e6] (metres)"},
    {"params.s_range", DomainStage::params, true, true, 1, false, true, kRangeMax, "an integer in [1, 1048576]"},
    {"params.a1", DomainStage::params, false, true, 0, true, false, 0, "a finite number > 0"},
    {"params.a2", DomainStage::params, false, true, 0, true, false, 0, "a finite number > 0"},
    {"params.epsilon", DomainStage::params, false, true, 0, false, false, 0, "a finite number >= 0"},
    {"params.max_ph", DomainStage::params, false, true, 0, false, false, 0, "a finite number >= 0"},
    {"params.ertu", DomainStage::params, false, true, 0, false, false, 0, "a finite number >= 0"},
    {"params.eta", DomainStage::params, false, true, 0, true, false, 0, "a finite number > 0"},
    {"params.phi", DomainStage::params, false, false, 0, false, false, 0, "a finite number"},
    {"params.lambda", DomainStage::params, false, false, 0, false, false, 0, "a finite number"},
    {"params.step_size", DomainStage::params, false, true, 0, true, true, 1e6, "a number in (0, 1e6] (seconds)"},
    {"max_steps", DomainStage::after_params, true, true, 0, false, true, static_cast<double>(kStepsMax),
     "an integer in [0, 2^31 - 1]"},
}};

// Whether v lies in d (integers: v is integral already, from the typed field).
inline bool in_domain(const Domain& d, double v) {
  if (!d.integer && !(v - v == 0)) return false;   // NaN or infinite
  if (d.has_min && (d.min_exclusive ? !(v > d.min) : !(v >= d.min))) return false;
  if (d.has_max && !(v <= d.max)) return false;
  return true;
}

// The rules across keys, in the order validate() applies them (names used by the schema).
inline constexpr std::array<std::string_view, 7> kScenarioRules{
    "obstacles-in-map-and-distinct", "robots-present", "robots-in-map", "robots-off-obstacles",
    "robots-distinct", "cosim-step-bound", "deposit-bound"};

}  // namespace swarmcheck::exploration
