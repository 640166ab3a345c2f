#pragma once
// The occupancy obligation (exposed for the tests). Its parts:
//   the choice lemma   for a window of any contents (each cell present or outside the map,
//                      blocked or free, any pheromone), the spec's choose_rule, interpreted
//                      symbolically, sends the robot to a present free candidate or keeps it
//                      where it is;
//   the planning step  spec's own stage (IndexOrder::plan: plan_robot, decide_on_grid,
//                      gather_candidates, window_around, choose, decide, the grid effects)
//                      interpreted on a symbolic map of any size with any contents: from a state
//                      in which every robot is in the map, off obstacles and named by the grid
//                      as its cell's occupant, the step keeps all three (so no two robots share a
//                      cell): bounded, whole steps of 1..3 robots; for every number of robots, by
//                      induction over the robots' loop, one robot's plan_robot against any other.
#include <vector>

#include <optional>

#include "proofs/obligations/obligation.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/choice.hpp"

namespace swarmcheck::proofs::occupancy {

// The window of s_range cells around a robot, raster order, without its own cell: a symbolic
// candidate per cell, named "<prefix>_<k>".
std::vector<exploration::SymbolicCandidate> symbolic_window(int s_range, const std::string& prefix);

// The target index choose_rule gives for these candidates (8-bit signed, -1: stay), and the
// negation of the lemma for it: with free_target, the target is -1 or a present free candidate;
// without, the best and the target are each -1 or a present candidate.
struct ChoiceQuery {
  z3::expr target;
  z3::expr violates;   // target names an absent or blocked candidate (or the best an absent one)
};
ChoiceQuery choice_query(Translator& t, const exploration::RuleDescriptor& rules,
                         const std::vector<exploration::SymbolicCandidate>& cands, bool free_target = true);

// The choice lemma for one rule set and window size: nullopt when it holds, else the outcome (a
// counterexample confirmed by the executed choose(), or unknown). Used by pheromone-bounds too.
std::optional<Outcome> choice_lemma(Session& session, exploration::RuleSet set, int s_range, bool free_target);

// The robots' cells after IndexOrder::plan on a symbolic world of `robots` robots (the step's
// symbolic interpretation from its entry point): what the occupancy property reads.
std::vector<sym::NodePtr> planning_step_quantities(exploration::RuleSet rule, int s_range, int robots);

}  // namespace swarmcheck::proofs::occupancy
