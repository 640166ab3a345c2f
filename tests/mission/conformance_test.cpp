// The mission runner against the reference model's run (model/mission/run_model) on generated
// missions: every field of the result and every event and step record, doubles by bits. A
// failure shrinks to a minimal mission, written with its FSM into $SWARMCHECK_CEX_DIR (default
// ./mission-counterexamples) as files `swarmcheck mission run` replays.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include "conformance/common/campaign.hpp"
#include "conformance/mission/counterexample.hpp"
#include "conformance/mission/differential.hpp"
#include "conformance/mission/generate.hpp"
#include "model/mission/thesis_dijkstra.hpp"
#include "spec/util/hana_diff.hpp"
#include "spec/util/hana_json.hpp"
#include "swarmcheck/mission.hpp"

namespace {

namespace sm = swarmcheck::mission;
namespace cm = swarmcheck::conformance::mission;

// Seeded, so the campaign is the same cases every time (RC_PARAMS set by the caller wins):
// 300 cases, about a second. Set before main, so before RapidCheck reads its configuration.
const bool kSeeded = [] { return ::setenv("RC_PARAMS", "seed=9 max_success=300", 0) == 0; }();

std::string cex_dir() {
  const char* d = std::getenv("SWARMCHECK_CEX_DIR");
  return d ? d : "mission-counterexamples";
}

std::string ending(const sm::RunResult& r) {
  if (r.completed) return "complete";
  return r.reason.substr(0, r.reason.find(' ', r.reason.find(' ') + 1));
}

RC_GTEST_PROP(MissionConformance, ImplRunEqualsModelRunOnGeneratedMissions, ()) {
  const cm::RunCase c = *cm::run_case();
  RC_TAG(swarmcheck::json_io::enum_to_string(c.options.body), ending(sm::run_mission(c.mission, c.options)));
  if (const auto d = cm::diff_run(c.mission, c.options)) {
    const auto cex = cm::write_counterexample(cex_dir(), "run", c.mission, c.options, *d);
    RC_FAIL(*d + "\nreplay: " + cex.command);
  }
}

// The concurrent cases (allocation supervisors, several robots at work): the same, record for record.
RC_GTEST_PROP(MissionConformance, ImplRunEqualsModelRunOnGeneratedConcurrentMissions, ()) {
  const cm::RunCase c = *cm::concurrent_case();
  if (const auto d = cm::diff_run(c.mission, c.options)) {
    const auto cex = cm::write_counterexample(cex_dir(), "concurrent", c.mission, c.options, *d);
    RC_FAIL(*d + "\nreplay: " + cex.command);
  }
}

// Unknown obstacles and the range sensor (the campaign's sensing kind): the same, and the runs
// scan, learn cells, re-route and bump, library and model alike.
RC_GTEST_PROP(MissionConformance, ImplRunEqualsModelRunOnMissionsWithUnknownObstaclesAndASensor, ()) {
  const cm::RunCase c = *cm::sensing_case();
  const sm::RunResult r = sm::run_mission(c.mission, c.options);
  RC_TAG(r.bumps > 0 ? "bumped" : "no bump", r.replans_sensed > 0 ? "learnt cells" : "learnt nothing");
  if (const auto d = cm::diff_run(c.mission, c.options)) {
    const auto cex = cm::write_counterexample(cex_dir(), "sensing", c.mission, c.options, *d);
    RC_FAIL(*d + "\nreplay: " + cex.command);
  }
}

// What the sensing kind reaches, on 100 seeded cases: about half the runs learn cells of unknown
// obstacles and re-route, a fifth bump into them (half the sensors are one beam of a quarter metre).
TEST(MissionConformance, SensingCasesOftenLearnCellsAndBump) {
  int bumped = 0, learnt = 0;
  const auto run = swarmcheck::conformance::run_campaign("sensing cases", 5, 100, [&] {
    const cm::RunCase c = *cm::sensing_case();
    const sm::RunResult r = sm::run_mission(c.mission, c.options);
    bumped += r.bumps > 0 ? 1 : 0;
    learnt += r.replans_sensed > 0 ? 1 : 0;
  });
  ASSERT_FALSE(run.failed);
  EXPECT_EQ(run.cases_run, 100);
  EXPECT_GE(learnt, 45) << bumped << " bumped";
  EXPECT_GE(bumped, 20) << learnt << " learnt";
}

// The thesis mission, both bodies, to the end (8 434 unicycle steps): record for record.
TEST(MissionConformance, ThesisMissionRunsTheSameOnImplAndModel) {
  const sm::Mission m = sm::load_mission(SWARMCHECK_SCENARIOS "/thesis/thesis-mission.json");
  for (const auto body : {sm::BodyModel::unicycle, sm::BodyModel::kinematic}) {
    sm::RunOptions o;
    o.body = body;
    EXPECT_EQ(cm::diff_run(m, o).value_or(""), "");
  }
}

// The canary: a model that follows the thesis's baseline plans instead of the exact ones must
// be told apart, or the harness could not catch a wrong choice. (The baseline may also choose
// controllable events in a circle forever; a run that never ends is wrong too, so the planner
// gives up after a bound.)
TEST(MissionConformance, CanaryRunOnTheBaselinePlannerIsCaught) {
  const bool passed = rc::check("canary: the model plans with the thesis's modified Dijkstra", [] {
    const cm::RunCase c = *cm::run_case();
    std::size_t calls = 0;
    const cm::PlanFunction baseline = [&](const sm::PlanQuery& q) {
      if (++calls > 100'000) throw std::runtime_error("the run does not end");
      return swarmcheck::model::mission::thesis_plan(c.mission, q);
    };
    RC_ASSERT(!cm::diff_run(c.mission, c.options, baseline).has_value());
  });
  EXPECT_FALSE(passed) << "the harness did not catch a run that follows other plans";
}

// The counterexample writer's files load as a mission that runs exactly as the original.
TEST(MissionConformance, CounterexampleFilesReplayTheSameRun) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("swarmcheck_mission_cex_" + std::to_string(::getpid()));
  // Worlds included: a corridor (meetings), unknown obstacles and a sensor (sensing).
  const bool passed = rc::check("written missions load and run the same", [&] {
    const cm::RunCase c = *rc::gen::oneOf(cm::run_case(), cm::head_on_case(), cm::sensing_case());
    const auto cex = cm::write_counterexample(dir.string(), "case", c.mission, c.options, "none");
    const sm::Mission back = sm::load_mission(cex.mission_path);
    RC_ASSERT(back.world.has_value() == c.mission.world.has_value());
    const auto a = sm::run_mission(c.mission, c.options);
    const auto b = sm::run_mission(back, c.options);
    const auto d = swarmcheck::json_io::first_difference(a, b);
    RC_ASSERT(!d.has_value());
  });
  EXPECT_TRUE(passed);
  std::filesystem::remove_all(dir);
}

}  // namespace
