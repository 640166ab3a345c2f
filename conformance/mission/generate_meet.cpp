// Generated head-on meetings (local steering, spec/mission/steering.hpp): two robots with radii
// swapping the ends of a line, both at once, in the open or in a corridor.
#include <string>

#include "conformance/mission/generate.hpp"

namespace swarmcheck::conformance::mission {

namespace {

namespace sm = swarmcheck::mission;
namespace sv = swarmcheck::supervisor;

// scenarios/examples/two-tasks.fsm: a does t1 and enters g1, b does t2 and enters g2, in any
// interleaving.
sv::Automaton two_tasks_fsm() {
  sv::Automaton a;
  a.states = {"sii", "siw", "sid", "swi", "sww", "swd", "sdi", "sdw", "sdd"};
  const auto edge = [&](const char* from, const char* e, const char* to, bool controllable) {
    a.delta[from].emplace(e, to);
    a.events[e] = sv::EventAttr{controllable, true};
  };
  edge("sii", "a1s", "swi", true);
  edge("sii", "b2s", "siw", true);
  edge("siw", "a1s", "sww", true);
  edge("siw", "b2f", "sid", false);
  edge("sid", "a1s", "swd", true);
  edge("swi", "a1f", "sdi", false);
  edge("swi", "b2s", "sww", true);
  edge("sww", "a1f", "sdw", false);
  edge("sww", "b2f", "swd", false);
  edge("swd", "a1f", "sdd", false);
  edge("sdi", "b2s", "sdw", true);
  edge("sdw", "b2f", "sdd", false);
  a.marked.insert("sdd");
  return a;
}

}  // namespace

rc::Gen<RunCase> head_on_case() {
  return rc::gen::exec([] {
    const double length = *rc::gen::inRange(6, 17) * 0.5;
    const double offset = *rc::gen::inRange(-3, 4) * 0.1;
    sm::MissionDecl d;
    d.fsm = "two-tasks.fsm";
    d.initial_state = "sii";
    d.marked_states = {"sdd"};
    d.robots = {sm::RobotDecl{"a", {0, 0}}, sm::RobotDecl{"b", {length, offset}}};
    d.tasks = {sm::TaskDecl{"t1", {length, offset}}, sm::TaskDecl{"t2", {0, 0}}};
    d.regions = {sm::RegionDecl{"g1", {sm::Point{length - 0.5, offset - 0.5}, sm::Point{length + 0.5, offset + 0.5}}},
                 sm::RegionDecl{"g2", {sm::Point{-0.5, -0.5}, sm::Point{0.5, 0.5}}}};
    d.events["a1s"] = sm::MeaningDecl{"a", "t1", std::nullopt};
    d.events["b2s"] = sm::MeaningDecl{"b", "t2", std::nullopt};
    d.events["a1f"] = sm::MeaningDecl{"a", std::nullopt, "g1"};
    d.events["b2f"] = sm::MeaningDecl{"b", std::nullopt, "g2"};
    d.radii = {*rc::gen::element(0.2, 0.4, 0.6), *rc::gen::element(0.2, 0.4, 0.6)};
    if (*rc::gen::arbitrary<bool>()) {  // in a corridor: the world's border, 2.5..4 m wide
      const double width = *rc::gen::element(2.5, 3.0, 4.0);
      sm::WorldDecl w;
      w.resolution_m = 0.25;
      w.origin = {-1.5, -width / 2};
      w.size_m = sm::Point{length + 3.0, width};
      d.world = w;
    }
    RunCase c{sm::check_mission(d, two_tasks_fsm(), "generated"), {}};
    c.options.body = *rc::gen::element(sm::BodyModel::kinematic, sm::BodyModel::unicycle);
    c.options.dt_s = *rc::gen::element(0.05, 0.1);
    c.options.max_time_s = 600;
    return c;
  });
}

}  // namespace swarmcheck::conformance::mission
