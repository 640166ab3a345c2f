#pragma once
// Invariants of the exploration system as predicates over the observable state. Each returns
// an empty string when it holds, else a sentence naming the first violation. The model checks
// them after every step (SWARM_DEMAND); the tests and the conformance harness check them too.
#include <span>
#include <string>

#include "spec/exploration/types.hpp"

namespace swarmcheck::exploration {

// Fixed rule sets: no two robots in one cell, none on an obstacle, every robot in the map.
std::string check_occupancy(const Scenario& s, std::span<const RobotRecord> robots);

// All rule sets: 0 <= visited, eP in [0, 100] for the fixed rule sets, sTime >= 0.
std::string check_progress(const Scenario& s, const StepRecord& r);

// Servo commands always within [-1, 1] (never NaN).
std::string check_servos(std::span<const RobotRecord> robots);

}  // namespace swarmcheck::exploration
