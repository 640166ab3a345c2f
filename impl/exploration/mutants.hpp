#pragma once
// Injected faults, for the conformance harness's mutation check (tests/conformance). A normal
// build has SWARMCHECK_MUTANT = 0 and none of them; a mutant build (-DSWARMCHECK_MUTANT=k)
// has exactly fault k, and `swarmcheck conform` must catch it with a minimal trace.
//   1  fixed rule sets deposit around the chosen cell instead of the robot's actual cell
//   2  the candidate window's upper i edge is one cell short
//   3  the wrong tie rule: the first minimum wins instead of the last
//   4  the evaporation clamp at 0 is removed
//   5  evaporation is skipped on planning steps
//   6  a decision ignores the moves of the robots before it in the same step
#ifndef SWARMCHECK_MUTANT
#define SWARMCHECK_MUTANT 0
#endif

namespace swarmcheck::impl {
inline constexpr int kMutant = SWARMCHECK_MUTANT;
inline constexpr int kMutantCount = 6;
}  // namespace swarmcheck::impl
