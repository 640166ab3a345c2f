// A program using the swarmcheck mission library: load the thesis's mission, plan it exactly,
// and run it in simulation with kinematic bodies.
//   mission MISSION.json
#include <cstdio>
#include <swarmcheck/mission.hpp>

namespace sm = swarmcheck::mission;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: mission MISSION.json\n");
    return 2;
  }
  try {
    const sm::Mission m = sm::load_mission(argv[1]);  // the file and the FSM it names, checked
    sm::Planner planner(m);
    const sm::Plan p = planner.plan(sm::initial_query(m));
    if (!p.found) return 1;
    std::printf("plan: %zu events, makespan %.3f m, total %.3f m\n", p.events.size(),
                p.cost.makespan, p.cost.total);
    sm::RunOptions o;
    o.body = sm::BodyModel::kinematic;
    const sm::RunResult r = sm::run_mission(m, o);
    std::printf("run: %s at t=%.2f s in state %s after %zu events\n", r.reason.c_str(), r.time_s,
                r.final_state.c_str(), r.events.size());
    return r.completed ? 0 : 1;
  } catch (const swarmcheck::InputError& e) {
    std::fprintf(stderr, "mission: %s\n", e.what());
    return 2;
  }
}
