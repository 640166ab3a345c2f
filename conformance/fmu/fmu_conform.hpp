#pragma once
// `swarmcheck conform --fmu`: anyone's FMUs of system A (an Environment, a Controller and a Body
// that form the thesis's loop, or a Controller or a Body alone: component_conform.hpp) checked
// against swarmcheck's model in lock-step on generated cases.
// Each case is a scenario with the robot and obstacle counts the Environment FMU declares (its
// xDesired{i} outputs and ox_{k} parameters); it is written as an INTO-CPS multi-model naming the
// user's FMU files, with every parameter the scenario decides, and run by swarmcheck's master
// (Jacobi, fixed step) in a child process with a time limit, beside the model with the same
// scenario. After every step every output the loop connects (each Body's robot_x, robot_y,
// robot_theta, each Controller's servos and onDestinationOutput, the Environment's waypoints,
// onDestinationOutput, eP and sTime) is compared with the model's: by bits unless a tolerance is
// given. On the first difference RapidCheck shrinks the case; the minimal one is written as a
// folder that `swarmcheck cosim` (or any INTO-CPS-style master) runs as it is, with the scenario
// for `swarmcheck run` and the first differing variable and step. A crash, an fmi2Error or a hang
// of an FMU is a difference like any other ("impl crashed with SIGSEGV at step 7").
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "spec/exploration/types.hpp"

namespace swarmcheck::conformance::fmu {

// Whose variable names the FMUs have (fmi/fmu/ports.hpp or thesis_ports.hpp).
enum class FmuInterface { swarmcheck, thesis };

// What counts as equal: |fmu - model| <= absolute + relative |model| (both 0: the same bits).
struct Tolerance {
  double absolute = 0.0;
  double relative = 0.0;
  bool bits() const { return absolute == 0.0 && relative == 0.0; }
  // Whether the FMU's value counts as the model's (NaN equals NaN only).
  bool accepts(double model, double fmu) const;
};

struct FmuConformOptions {
  std::string environment, controller, body;   // the FMU files
  FmuInterface interface = FmuInterface::swarmcheck;
  // What the model runs (and the cases' rule set, drawn when not given).
  std::optional<exploration::RuleSet> rule;
  exploration::ControllerKind controller_law = exploration::ControllerKind::swarmcheck;
  exploration::BodyKind body_kind = exploration::BodyKind::kinematic;
  int cases = 30;
  uint64_t seed = 1;
  int64_t max_steps = 300;                       // master steps per case at most
  std::string out_dir = "conform-out";
  std::chrono::milliseconds quiet_limit{std::chrono::seconds(60)};
  Tolerance tolerance;
  std::function<void(int, int)> on_case;
};

struct FmuDivergence {
  int64_t step = 0;            // the master step after which it was seen (0: after initialisation)
  std::string variable;        // "{Body}.body2.robot_x"
  double model = 0.0, fmu = 0.0;
  std::string abnormal_end;    // "impl crashed with SIGSEGV at step 7", or an FMU's error
  std::string describe() const;
};

struct FmuCounterexample {
  exploration::Scenario minimal;
  FmuDivergence divergence;
  std::string folder;          // multimodel.json, coe.json, scenario.json, divergence.json, README
  int shrinks = 0;
};

struct FmuConformReport {
  std::string checked = "loop";    // "loop" (Environment, Controller, Body), "controller" or "body" alone
  int robots = 0, obstacles = 0;   // what the Environment FMU declares (the loop)
  int cases_run = 0;
  std::optional<FmuCounterexample> counterexample;
};

// InputError for FMU files that cannot be read or do not form the loop.
FmuConformReport run_fmu_conform(const FmuConformOptions& o);

}  // namespace swarmcheck::conformance::fmu
