#pragma once
// The occupancy obligation, in two parts (exposed for the tests):
//   the choice lemma   for a window of any contents (each cell present or outside the map,
//                      blocked or free, any pheromone), the spec's choose_rule, interpreted
//                      symbolically, sends the robot to a present free candidate or keeps it
//                      where it is;
//   the planning step  robots at symbolic cells of a symbolic map with free obstacles decide in
//                      index order, each through any choice the lemma allows, seeing earlier
//                      robots' moves at once: every robot stays in the map, off obstacles and
//                      alone in its cell (checked for one mover against any other robot, which
//                      covers every number of robots).
#include <vector>

#include "proofs/obligations/translate.hpp"
#include "spec/exploration/choice.hpp"

namespace swarmcheck::proofs::occupancy {

// The window of s_range cells around a robot, raster order, without its own cell: a symbolic
// candidate per cell, named "<prefix>_<k>".
std::vector<exploration::SymbolicCandidate> symbolic_window(int s_range, const std::string& prefix);

// The target index choose_rule gives for these candidates (8-bit signed, -1: stay), and the
// negation of the lemma for it.
struct ChoiceQuery {
  z3::expr target;
  z3::expr violates;   // target names an absent or blocked candidate
};
ChoiceQuery choice_query(Translator& t, const exploration::RuleDescriptor& rules,
                         const std::vector<exploration::SymbolicCandidate>& cands);

}  // namespace swarmcheck::proofs::occupancy
