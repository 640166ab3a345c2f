// Execution of the thesis mission, and replay of its trace: every event was enabled where it
// fired, and the avoidance rule held at every step (every region entry seen in the positions
// fired its event in that step; no robot entered a region whose event was not enabled).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "impl/mission/trace.hpp"
#include "tests/mission/replay.hpp"
#include "swarmcheck/mission.hpp"
#include "spec/mission/avoidance.hpp"
#include "spec/mission/plan.hpp"

namespace {

namespace sm = swarmcheck::mission;
namespace im = swarmcheck::impl::mission;
using swarmcheck::test::replay;
const std::string kMission = SWARMCHECK_SCENARIOS "/thesis/thesis-mission.json";

std::size_t position_of(const sm::RunResult& r, const std::string& event) {
  for (std::size_t k = 0; k < r.events.size(); ++k)
    if (r.events[k].event == event) return k;
  ADD_FAILURE() << event << " never fired";
  return r.events.size();
}

double time_of(const sm::RunResult& r, const std::string& event) {
  const std::size_t k = position_of(r, event);
  return k < r.events.size() ? r.events[k].time_s : -1.0;
}

void run_and_replay(sm::BodyModel body) {
  const auto m = sm::load_mission(kMission);
  const auto run = swarmcheck::test::run_traced(m, body);
  const auto& r = run.result;
  const auto& t = run.trace;
  ASSERT_TRUE(r.completed) << r.reason;
  EXPECT_EQ(r.final_state, "s134:146:143");
  EXPECT_EQ(r.reason, "mission complete");
  EXPECT_EQ(replay(m, t), "");
  // The robots did the planned tasks: A 3 then 4, B 1 then 2; B starts as soon as the
  // supervisor allows it (state s14, A on its way to task 3), not after A's tasks.
  std::vector<std::string> starts;
  for (const auto& e : r.events)
    if (e.controllable) starts.push_back(e.event);
  EXPECT_EQ(starts, (std::vector<std::string>{"a3s", "b1s", "b2s", "a4s"}));
  EXPECT_EQ(r.events[position_of(r, "b1s") - 1].state_after, "s14");
  EXPECT_LT(position_of(r, "b1s"), position_of(r, "a3f"));
  EXPECT_LT(position_of(r, "b1s"), position_of(r, "a4f"));
  EXPECT_LT(time_of(r, "b1s"), time_of(r, "a4f"));
  // The trace's intervals are the result's, and B was busy before A's last task ended.
  EXPECT_EQ(t.intervals.size(), r.intervals.size());
  bool b_busy_early = false;
  for (const auto& i : t.intervals)
    b_busy_early = b_busy_early || (i.robot == "B" && i.activity == sm::Activity::busy &&
                                    i.from_s < time_of(r, "a4f"));
  EXPECT_TRUE(b_busy_early);
}

TEST(MissionRun, ThesisMissionCompletesWithUnicycleBodiesAndItsTraceReplays) {
  run_and_replay(sm::BodyModel::unicycle);
}

TEST(MissionRun, ThesisMissionCompletesWithKinematicBodiesAndItsTraceReplays) {
  run_and_replay(sm::BodyModel::kinematic);
}

TEST(MissionRun, ReplayCatchesAnEventThatWasNotEnabled) {
  const auto m = sm::load_mission(kMission);
  im::MissionTrace t;
  t.initial_state = "s1";
  im::TraceEntry e;
  e.is_event = true;
  e.event = sm::EventRecord{0.0, "a3s", "A", true, "s9"};
  t.entries.push_back(e);
  EXPECT_EQ(replay(m, t), "event a3s fired in state s1, where it is not enabled");
}

// The public trace file: nothing at the path until commit(), then exactly the writer's records;
// dropped without commit(), it leaves no file (not even a temporary one) behind.
TEST(MissionRun, TraceFileAppearsWholeOnCommitOnly) {
  const auto m = sm::load_mission(kMission);
  sm::RunOptions o;
  o.body = sm::BodyModel::kinematic;
  const auto dir = std::filesystem::temp_directory_path() /
                   ("swarmcheck_trace_file_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "t.jsonl").string();
  {
    sm::TraceFile dropped(path, m, o);
    sm::run_mission(m, o, &dropped);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  sm::TraceFile trace(path, m, o);
  const auto r = sm::run_mission(m, o, &trace);
  EXPECT_FALSE(std::filesystem::exists(path));
  trace.commit();
  std::ifstream in(path);
  const auto t = im::read_trace(in, path);
  std::size_t events = 0;
  for (const auto& e : t.entries) events += e.is_event ? 1 : 0;
  EXPECT_EQ(events, r.events.size());
  EXPECT_EQ(replay(m, t), "");
  std::filesystem::remove_all(dir);
}

// Issue 14's three-robot case: a supervisor that lets one robot work at a time, and a plan that
// gives each robot one task (20 m each). The robot that finishes first sits within 4.5 m of the
// other tasks; execution must still follow the plan (before, one robot did all three).
void three_robots(sm::BodyModel body) {
  const auto m = sm::load_mission(SWARMCHECK_SCENARIOS "/examples/three-robots.json");
  const sm::Plan p = sm::Planner(m).plan(sm::initial_query(m));
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.cost.makespan, 20.0);
  const auto planned = sm::task_sequences(m, p.events);
  EXPECT_EQ(planned, (std::vector<std::vector<std::size_t>>{{0}, {1}, {2}}));
  const auto run = swarmcheck::test::run_traced(m, body);
  const auto& r = run.result;
  ASSERT_TRUE(r.completed) << r.reason;
  EXPECT_EQ(replay(m, run.trace), "");
  std::vector<std::string> starts;
  for (const auto& e : r.events)
    if (e.controllable) starts.push_back(e.event);
  EXPECT_EQ(sm::task_sequences(m, starts), planned);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_GT(r.travel[k], 19.0) << m.robots[k].name;  // each drove to its own task
    EXPECT_LT(r.travel[k], 21.0) << m.robots[k].name;
  }
}

TEST(MissionRun, ThreeRobotsOneAtATimeEachDoesThePlannedTaskKinematic) {
  three_robots(sm::BodyModel::kinematic);
}

TEST(MissionRun, ThreeRobotsOneAtATimeEachDoesThePlannedTaskUnicycle) {
  three_robots(sm::BodyModel::unicycle);
}

TEST(MissionRun, TimeLimitIsReported) {
  const auto m = sm::load_mission(kMission);
  sm::RunOptions o;
  o.max_time_s = 1.0;
  const auto r = sm::run_mission(m, o);
  EXPECT_FALSE(r.completed);
  EXPECT_EQ(r.reason, "time limit of 1 s reached");
}

}  // namespace

TEST(MissionRun, AMalformedTraceRecordIsRefusedWithItsLineAndJsonPath) {
  const std::string header =
      R"({"type":"header","format":"swarmcheck-mission-trace","version":1,"mission":"m.json","fsm":"c.fsm","initial_state":"s1","robots":["A","B"],"body":"unicycle","dt":0.05})";
  const std::string step = R"({"type":"step","t":0.0,"state":"s1","positions":[[0,0],[1,1]],"blocked":[false,false],"yielded":[false,false]})";
  const auto error_of = [&](const std::string& second) {
    std::istringstream in(header + "\n" + second + "\n");
    try {
      swarmcheck::impl::mission::read_trace(in, "t.jsonl");
    } catch (const swarmcheck::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_of(step), "(no error)");
  EXPECT_EQ(error_of(R"({"type":"step","t":0.0,"state":"s1","positions":[["x",0],[1,1]],"blocked":[false,false]})"),
            "t.jsonl:2: positions[0][0]: expected a number, got a string");
  EXPECT_EQ(error_of(R"({"t":0.0})"), "t.jsonl:2: type: missing");
  EXPECT_EQ(error_of(R"({"type":"step","t":"0","state":"s1","positions":[],"blocked":[]})"), "t.jsonl:2: t: expected a number, got a string");
  EXPECT_EQ(error_of(R"({"type":"step","t":0.0,"state":"s1","positions":[[0,0]],"blocked":[false]})"),
            "t.jsonl:2: a step record has 1 positions, 1 blocked and 1 yielded flags; the header names 2 robots");
  EXPECT_EQ(error_of("[1, 2]"), "t.jsonl:2: expected a JSON object, got a list");
  // Beyond the fields: times, order, robots, the header first.
  EXPECT_EQ(error_of(R"({"type":"step","t":-1,"state":"s1","positions":[[0,0],[1,1]],"blocked":[false,false]})"),
            "t.jsonl:2: t: expected a time >= 0 s, got -1");
  EXPECT_EQ(error_of(R"({"type":"event","t":0,"event":"a3s","robot":"C","kind":"c","state":"s2"})"),
            "t.jsonl:2: robot: \"C\" is not a robot of the header");
  EXPECT_EQ(error_of(R"({"type":"interval","robot":"A","activity":"busy","from":2,"to":1})"),
            "t.jsonl:2: to: expected a time >= from (2), got 1");
  EXPECT_EQ(error_of(header), "t.jsonl:2: a second header");
  const auto in_order = [&](const std::string& a, const std::string& b) {
    std::istringstream in(header + "\n" + a + "\n" + b + "\n");
    try {
      swarmcheck::impl::mission::read_trace(in, "t.jsonl");
    } catch (const swarmcheck::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  const std::string later = R"({"type":"step","t":0.5,"state":"s1","positions":[[0,0],[1,1]],"blocked":[false,false]})";
  EXPECT_EQ(in_order(later, step), "t.jsonl:3: t: expected records in time order, got 0 after 0.5");
  EXPECT_EQ(in_order(step, later), "(no error)");
  EXPECT_EQ(in_order(step, step), "t.jsonl:3: t: expected a time after the last step's (0), got 0");
  const std::string busy = R"({"type":"interval","robot":"A","activity":"busy","from":0,"to":2})";
  EXPECT_EQ(in_order(busy, R"({"type":"interval","robot":"A","activity":"busy","from":1,"to":3})"),
            "t.jsonl:3: from: expected a time >= 2 (where robot A's last interval ended), got 1");
  EXPECT_EQ(in_order(busy, R"({"type":"interval","robot":"B","activity":"busy","from":1,"to":3})"), "(no error)");
  EXPECT_EQ(error_of(R"({"type":"step","t":0.0,"state":"s1","positions":[[0,0],[1,1]],"blocked":[false,false],"blockd":[]})"),
            "t.jsonl:2: blockd: unknown field (a step record has type, t, state, positions, blocked, yielded)");
  std::istringstream headless(step + "\n");
  EXPECT_THROW(swarmcheck::impl::mission::read_trace(headless, "t.jsonl"), swarmcheck::InputError);
}
