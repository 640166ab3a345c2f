#pragma once
// Bodies and controllers (DESIGN.md, "the real system"; spec/SPEC.md sections 8 and 9): each is
// ONE row of kBodies / kControllers, like a rule set (rule_set.hpp). A row names the dynamics or
// the law the robot stage runs; model/ and impl/ read these fields and never test which body or
// controller it is. A preset is a named combination of rows and a rule set.
#include <array>
#include <cstddef>
#include <string_view>
#include <utility>

#include "spec/exploration/rule_set.hpp"
#include "spec/util/hana_json.hpp"

namespace swarmcheck::exploration {

enum class BodyKind { kinematic, intocps };
enum class ControllerKind { swarmcheck, thesis };

// How a body moves over a master step (body.hpp, body_intocps.hpp).
enum class BodyDynamics {
  steady_state_unicycle,   // v, omega of the servos held over the step, exact unicycle integration
  twenty_sim_rk4,          // the 20-sim Body_Block: 16 states, RK4 at 1 ms, the reported point ahead of the axle
};

// Which control law a controller step runs (controller.hpp, controller_thesis.hpp).
enum class ControllerLaw {
  latched_two_phase,       // swarmcheck's: orientation target held while turning, gains capped by the step
  published_uncontroller,  // the thesis's UController as its binary computes it
};

struct BodyDescriptor {
  BodyKind id;
  std::string_view name;      // the scenario file's and the command line's spelling
  BodyDynamics dynamics;
  std::string_view summary;   // for --help
};

struct ControllerDescriptor {
  ControllerKind id;
  std::string_view name;
  ControllerLaw law;
  std::string_view summary;
};

inline constexpr std::array<BodyDescriptor, 2> kBodies{{
    {BodyKind::kinematic, "kinematic", BodyDynamics::steady_state_unicycle,
     "the Body_Block's steady state: exact unicycle integration of the servos' wheel speeds (the default)"},
    {BodyKind::intocps, "intocps", BodyDynamics::twenty_sim_rk4,
     "thesis A's 20-sim Body_Block as its FMU computes it: motors, PI speed loops, mass, slip, RK4 at 1 ms"},
}};

inline constexpr std::array<ControllerDescriptor, 2> kControllers{{
    {ControllerKind::swarmcheck, "swarmcheck", ControllerLaw::latched_two_phase,
     "two-phase point-to-point control that arrives on both bodies at steps up to 0.5 s (the default)"},
    {ControllerKind::thesis, "thesis", ControllerLaw::published_uncontroller,
     "thesis A's published UController, as its binary computes it (bugs included)"},
}};

constexpr const BodyDescriptor& body_of(BodyKind k) { return kBodies[static_cast<std::size_t>(k)]; }
constexpr const ControllerDescriptor& controller_of(ControllerKind k) {
  return kControllers[static_cast<std::size_t>(k)];
}

constexpr bool robot_rows_in_enumerator_order() {
  for (std::size_t k = 0; k < kBodies.size(); ++k)
    if (static_cast<std::size_t>(kBodies[k].id) != k) return false;
  for (std::size_t k = 0; k < kControllers.size(); ++k)
    if (static_cast<std::size_t>(kControllers[k].id) != k) return false;
  return true;
}
static_assert(robot_rows_in_enumerator_order(), "kBodies / kControllers rows must follow their enumerators");

// A preset: a named combination of a rule set, a controller and a body.
struct Preset {
  std::string_view name;
  RuleSet rule;
  ControllerKind controller;
  BodyKind body;
  std::string_view summary;
};
inline constexpr std::array<Preset, 1> kPresets{{
    {"thesis", RuleSet::thesis, ControllerKind::thesis, BodyKind::intocps,
     "the published system: rule thesis, controller thesis, body intocps"},
}};
// The preset named `name`, or null.
constexpr const Preset* find_preset(std::string_view name) {
  for (const Preset& p : kPresets)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace swarmcheck::exploration

namespace swarmcheck::json_io {
template <>
struct EnumNames<exploration::BodyKind> {
  static constexpr auto names = [] {
    std::array<std::pair<exploration::BodyKind, std::string_view>, exploration::kBodies.size()> out{};
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = {exploration::kBodies[k].id, exploration::kBodies[k].name};
    return out;
  }();
};
template <>
struct EnumNames<exploration::ControllerKind> {
  static constexpr auto names = [] {
    std::array<std::pair<exploration::ControllerKind, std::string_view>, exploration::kControllers.size()> out{};
    for (std::size_t k = 0; k < out.size(); ++k)
      out[k] = {exploration::kControllers[k].id, exploration::kControllers[k].name};
    return out;
  }();
};
// A scenario that names no controller runs the default, and its files and traces stay as they were.
template <>
struct OmitWhenDefault<exploration::ControllerKind> : std::true_type {};
}  // namespace swarmcheck::json_io
