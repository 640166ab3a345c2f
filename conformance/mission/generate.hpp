#pragma once
// Generated missions (already consistent; built as values, not read from files).
//
// random_small_mission: 1..3 robots, 1..3 tasks, 2 regions, an FSM of 2..6 states whose edges
//   carry random task starts (controllable, "r<r>t<t>") and region entries (uncontrollable,
//   "r<r>g<g>") to random targets, 1..2 marked states. Small enough for brute force.
// run_case: a mission and run options for the differential runner (impl run vs model run):
//   1..3 robots starting outside every region, 1..3 tasks on integer points, a square region
//   around most tasks and up to two more rectangles (integer corners, so points may lie on
//   edges, which are outside), a task start "<robot>s<task>" and a region entry
//   "<robot>e<region>" declared for every pair, and an FSM whose path to the marked state has
//   robots start tasks and then enter regions (so they must drive there), plus up to three
//   states and random edges. It passes check_mission by construction. Options: either body, dt
//   of 0.05..0.5 s, a time limit of at most 1200 steps, speed 0.25..2 m/s.
// allocation_mission(robots, tasks, seed): the task-allocation supervisor: a state records each
//   task as free, in progress by one robot, or done; "r<r>s<t>" (controllable) starts a free task
//   on an idle robot, "r<r>f<t>" (uncontrollable, entry into the 2 m square around the task) ends
//   it; marked: all done. Task points and starts uniform in [-20, 20]^2 from `seed`.
#include <cstdint>
#include <string>
#include <vector>
#include <rapidcheck.h>

#include "spec/mission/mission.hpp"
#include "spec/mission/run.hpp"

namespace swarmcheck::conformance::mission {

rc::Gen<swarmcheck::mission::Mission> random_small_mission();
// Robots and tasks on the lattice {-3, 0, 3} x {-4, 0, 4} (distances mostly 3, 4, 5 and their
// multiples), and an FSM of 2..4 branches from q0 to one marked state, each of 1..3 task starts
// and region entries: branches tie on the makespan while totals and lengths differ.
rc::Gen<swarmcheck::mission::Mission> tie_mission();
// Two robots split two tasks either way and meet again in one FSM state, then more tasks follow:
// one (state, positions) node with two travel vectors (the planner's dominance test decides).
rc::Gen<swarmcheck::mission::Mission> swap_mission();

struct RunCase {
  swarmcheck::mission::Mission mission;
  swarmcheck::mission::RunOptions options;
};
rc::Gen<RunCase> run_case();
// run_case's mission as declared (before check_mission), for families that add to it.
struct RunDecl {
  swarmcheck::mission::MissionDecl decl;
  swarmcheck::supervisor::Automaton fsm;
};
rc::Gen<RunDecl> run_decl();
// run_case's options (drawn inside a generator: rc::gen::exec).
swarmcheck::mission::RunOptions draw_run_options();
// Unknown obstacles and the range sensor (spec/mission/sensing.hpp): half the cases a task
// allocation (1..3 robots, 1..3 tasks on integer points of [-7, 7]^2), half run_case's missions,
// in a 20 x 20 m world (cells of 0.25 or 0.5 m), robots of radius 0..0.3 m, unknown walls across
// the ways robots drive (start to task, task to task; now and then a known one), and, half the
// time, a nearly blind sensor (one beam of 0.25 m: the robots find walls by bumping into them,
// and a bump puts the cells the robot's disk overlaps on its map), else 3..24 beams of 1 or 3 m
// (they see walls and re-route first), with noise or none. Walls that would cover a start or a
// task, or cut a task or region off on the known map, are left out: the mission passes
// check_mission. Long enough (400 or 1200 steps) for the robots to reach the walls.
rc::Gen<RunCase> sensing_case();
// Head-on meetings (local steering): robots a at (0, 0) and b at (D, y) (D 3..8 m, |y| <= 0.3 m),
// radii 0.2..0.6 m, swap ends at once (two-tasks.fsm), in the open or (one case in two) in a
// corridor 2.5, 3 or 4 m wide (the world's border; 0.25 m cells); either body, dt 0.05 or 0.1 s.
rc::Gen<RunCase> head_on_case();

swarmcheck::mission::Mission allocation_mission(std::size_t robots, std::size_t tasks,
                                          std::uint64_t seed);
// The same supervisor with the given start and task points; at most `capacity` tasks are in
// progress at once, and at most `per_robot` of them on one robot (with 2, a robot may be given its
// next task before it has finished the one it is on).
swarmcheck::mission::Mission allocation_mission_at(const std::vector<swarmcheck::mission::Point>& starts,
                                                   const std::vector<swarmcheck::mission::Point>& tasks,
                                                   std::size_t capacity = SIZE_MAX, std::size_t per_robot = 1);
// A small one for brute force: 2..3 robots, 2..3 tasks (not both 3), points on the 3-4-5
// lattice (ties) or on integer points of [-10, 10]^2. Many paths reach one (state, positions)
// node with different travel: the planner's dominance test matters.
rc::Gen<swarmcheck::mission::Mission> small_allocation_mission();

// Concurrent execution (tests/mission/concurrent_test.cpp): an allocation mission of 1..3 robots
// and 1..4 tasks, at most 1..robots tasks in progress at once and 1 or 2 on one robot, in an
// obstacle-free world laid out so that no straight leg between starts and tasks enters another
// task's square (the tasks near a circle of radius 8..12 m, the starts within 3 m of its centre;
// half the time on a symmetric layout, so that assignments tie); the kinematic body, dt
// 0.05..0.2 s, speed 0.5..2 m/s, an hour of time.
rc::Gen<RunCase> concurrent_case();
// "The same plan robot by robot": the mission whose supervisor is the single path of `plan`'s
// events stably sorted by robot (robot 0's events first, in plan order, then robot 1's, ...);
// its alphabet is the mission's. Running it executes the plan one robot after another.
swarmcheck::mission::Mission robot_by_robot(const swarmcheck::mission::Mission& m,
                                            const std::vector<std::string>& plan);

}  // namespace swarmcheck::conformance::mission
