#pragma once
// The thesis's planner, kept as the baseline (UDM thesis, section 4 and Appendices J and K):
// func_calculateCosts builds a state-by-state adjacency matrix A and cost matrix C; the modified
// func_Dijkstra (J. Kirk's Dijkstra with per-robot accumulation TB) finds a path from the current
// state to the marked states. Written as the MATLAB does it, generalised from two robots to any
// number, with the event naming convention of the thesis ('a2s', 'a1f', 'a5e') replaced by the
// mission's meanings: 's' = a task start, 'f' = an entry into a region that contains a task point
// (that task, the first one in file order), 'e' = any other region entry.
//
// Its bugs, kept on purpose (docs/mission.md shows what they cost on generated missions):
//  1. Costs from the planning-time positions: every task's "From" is 'start' in the thesis's
//     user data, so a task start is costed from where the robot is when planning, never from the
//     task it will have done before.
//  2. The "subtracted distance": a state with a task-finish event, or entered by another robot's
//     start/finish event, gets every outgoing cost reduced by that event's own start distance,
//     clipped at 0 ("what happens if multiple events?" - the last one found wins).
//  3. The label of a state is not the makespan: when the robot changes along the path, the
//     "incremental cost" c + TB(I, bot(I,J)) - TB(I, bot(prevI, I)) makes it the accumulated
//     travel of the robot that moved last.
//  4. A relaxation that does not improve J still copies TB(I, :) into TB(J, :).
//  5. One label per state, settled once: with path-dependent costs Dijkstra's argument fails.
//  6. Parallel events between the same two states: the last (in name order) defines C and bot;
//     self-loops are dropped (A - diag(diag(A))).
//  7. If every adjacent cost is > 0 (no uncontrollable event), a label of exactly 0 counts as
//     "no label" (the sparse-table test ~TAB(J)).
// With several marked states the one with the least settled label is taken (first in the list
// on ties). The returned plan's cost is the spec's cost of the path it found.
#include "spec/mission/plan.hpp"

namespace swarmcheck::model::mission {

swarmcheck::mission::Plan thesis_plan(const swarmcheck::mission::Mission& m, const swarmcheck::mission::PlanQuery& q);

}  // namespace swarmcheck::model::mission
