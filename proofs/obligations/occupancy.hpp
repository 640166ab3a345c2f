#pragma once
// The fixed rule sets' choice (SPEC.md section 3) over symbolic candidates, for the occupancy
// obligation; exposed so that the tests can check it against spec/exploration/choice.cpp.
#include <vector>

#include "proofs/obligations/z3.hpp"

namespace swarmcheck::proofs::occupancy {

struct SymCandidate {   // one window cell in raster order, other than the robot's own
  z3::expr valid;       // in the map
  z3::expr key;         // pow(tau, phi): any real
  z3::expr blocked;     // obstacle or occupied
};

// deterministic: the last minimum of key in raster order; blocked: the first free candidate;
// none: stay. The target's index, -1 to stay.
z3::expr deterministic_target(z3::context& c, const std::vector<SymCandidate>& cands);

// stochastic: any minimum (best) and any free candidate (fallback), the two choices free
// integer variables constrained here; the target's index, -1 to stay.
z3::expr stochastic_target(z3::context& c, z3::solver& s, const std::vector<SymCandidate>& cands,
                           const z3::expr& tie_choice, const z3::expr& fallback_choice);

}  // namespace swarmcheck::proofs::occupancy
