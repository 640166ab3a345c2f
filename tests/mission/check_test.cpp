// Every mission-file problem gets one exact message at "file: json.path".
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "swarmcheck/mission.hpp"
#include "spec/util/input_error.hpp"

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;
const std::string kThesis = SWARMCHECK_SCENARIOS "/thesis";

// Writes the thesis mission, edited by `edit`, next to a copy of control2.fsm; returns the
// message load_mission throws (or "" when it loads).
std::string message_for(const std::function<void(Json&)>& edit, const std::string& raw = "") {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck_mission_check_" + std::to_string(::getpid()));
  fs::create_directories(d);
  fs::copy_file(kThesis + "/control2.fsm", d / "control2.fsm", fs::copy_options::overwrite_existing);
  std::ifstream in(kThesis + "/thesis-mission.json");
  Json j = Json::parse(in);
  edit(j);
  {
    std::ofstream out(d / "m.json");
    out << (raw.empty() ? j.dump(2) : raw);
  }
  try {
    swarmcheck::mission::load_mission((d / "m.json").string());
  } catch (const swarmcheck::InputError& e) {
    const std::string s = e.what();
    return s.substr(s.find("m.json: ") == std::string::npos ? 0 : s.find("m.json: ") + 8);
  }
  return "";
}

TEST(MissionCheck, TheThesisMissionLoads) {
  EXPECT_EQ(message_for([](Json&) {}), "");
}

TEST(MissionCheck, FsmEventWithoutMeaning) {
  EXPECT_EQ(message_for([](Json& j) { j["events"].erase("a3s"); }),
            "events: event \"a3s\" of control2.fsm has no meaning (expected \"a3s\": {\"robot\": "
            "..., \"task\": ...} or {\"robot\": ..., \"region\": ...})");
}

TEST(MissionCheck, UnknownRobotTaskAndRegionNames) {
  EXPECT_EQ(message_for([](Json& j) { j["events"]["a3s"]["robot"] = "C"; }),
            "events.a3s.robot: no robot named \"C\" (robots: A, B)");
  EXPECT_EQ(message_for([](Json& j) { j["events"]["a3s"]["task"] = "tsk9"; }),
            "events.a3s.task: no task named \"tsk9\" (tasks: tsk1, tsk2, tsk3, tsk4)");
  EXPECT_EQ(message_for([](Json& j) { j["events"]["a5e"]["region"] = "reg9"; }),
            "events.a5e.region: no region named \"reg9\" (regions: reg5, reg6, reg8, reg7, "
            "regtsk1, regtsk2, regtsk3, regtsk4)");
}

TEST(MissionCheck, MeaningNeedsExactlyOneOfTaskOrRegion) {
  EXPECT_EQ(message_for([](Json& j) { j["events"]["a3s"]["region"] = "reg5"; }),
            "events.a3s: expected exactly one of \"task\" (a task start) or \"region\" (a region "
            "entry)");
}

TEST(MissionCheck, UnknownStates) {
  EXPECT_EQ(message_for([](Json& j) { j["initial_state"] = "s999"; }),
            "initial_state: state \"s999\" is not in control2.fsm");
  EXPECT_EQ(message_for([](Json& j) { j["marked_states"] = Json::array({"zz"}); }),
            "marked_states[0]: state \"zz\" is not in control2.fsm");
  EXPECT_EQ(message_for([](Json& j) { j["marked_states"] = Json::array(); }),
            "marked_states: expected at least one marked state");
}

TEST(MissionCheck, StartInconsistentWithTheFirstEvents) {
  // A starting in region 6: a6e is not enabled in s1.
  EXPECT_EQ(message_for([](Json& j) { j["robots"][0]["start"] = Json::array({-9, 19}); }),
            "robots[0].start: robot A starts inside region reg6, so its entry event a6e fires at "
            "the start, but a6e is not enabled in state s1 (the initial state)");
  // B starting in region 5 next to A: b5e is not enabled after a5e.
  EXPECT_EQ(message_for([](Json& j) { j["robots"][1]["start"] = Json::array({-9, -10}); }),
            "robots[1].start: robot B starts inside region reg5, so its entry event b5e fires at "
            "the start, but b5e is not enabled in state s2 (after a5e)");
}

TEST(MissionCheck, DegenerateRegionCorners) {
  EXPECT_EQ(message_for([](Json& j) { j["regions"][0]["corners"] = Json::parse("[[0, 0], [0, 5]]"); }),
            "regions[0].corners: the corners [0, 0] and [0, 5] give a rectangle of zero width "
            "(expected two opposite corners with different x and different y)");
  EXPECT_EQ(message_for([](Json& j) { j["regions"][0]["corners"] = Json::parse("[[1, 2], [3, 2]]"); }),
            "regions[0].corners: the corners [1, 2] and [3, 2] give a rectangle of zero height "
            "(expected two opposite corners with different x and different y)");
}

TEST(MissionCheck, WrongTypesMissingAndUnknownKeys) {
  EXPECT_EQ(message_for([](Json& j) { j["robots"][0]["start"] = "here"; }),
            "robots[0].start: expected a list of 2 values, got a string");
  EXPECT_EQ(message_for([](Json& j) { j["tasks"][1].erase("at"); }),
            "tasks[1].at: missing (its position [x, y])");
  EXPECT_EQ(message_for([](Json& j) { j.erase("robots"); }),
            "robots: missing (a list of {\"name\", \"start\": [x, y]})");
  EXPECT_EQ(message_for([](Json& j) { j["events"] = Json::array(); }),
            "events: expected an object keyed by event name, got a list");
  EXPECT_EQ(message_for([](Json& j) { j["colour"] = "red"; }).substr(0, 21),
            "colour: unknown key (");
}

TEST(MissionCheck, DuplicateNamesAndControllability) {
  EXPECT_EQ(message_for([](Json& j) { j["robots"][1]["name"] = "A"; }),
            "robots[1].name: \"A\" is already the name of robots[0]");
  EXPECT_EQ(message_for([](Json& j) { j["events"]["a5e"] = Json{{"robot", "A"}, {"task", "tsk1"}}; }),
            "events.a5e: starts a task, so it must be controllable, but control2.fsm declares "
                "it uncontrollable (uc)");
  EXPECT_EQ(message_for([](Json& j) { j["events"]["a3s"] = Json{{"robot", "A"}, {"region", "reg5"}}; }),
            "events.a3s: is a region entry, which the robots cause, so it must be uncontrollable, "
            "but control2.fsm declares it controllable (c)");
  EXPECT_EQ(message_for([](Json& j) { j["events"]["b1s"]["robot"] = "A"; }),
            "events.b1s: has the same meaning as events.a1s");
}

TEST(MissionCheck, MissingFsmAndBadJson) {
  EXPECT_NE(message_for([](Json& j) { j["fsm"] = "nope.fsm"; })
                .find("fsm: cannot open the FSM file \"nope.fsm\""),
            std::string::npos);
  EXPECT_NE(message_for([](Json&) {}, "{\"fsm\": ").find("not valid JSON"), std::string::npos);
}

}  // namespace
