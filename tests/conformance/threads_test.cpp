// Planning and deposits in parallel over strips of the map (impl/exploration/strip_schedule.hpp)
// against one thread: the same bits, step by step, whatever the number of threads and however the
// robots lie (dense or sparse, near strip edges or not, every window size).
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <numeric>

#include "model/exploration/exploration_model.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/exploration/scenario.hpp"
#include "swarmcheck/exploration.hpp"
#include "impl/exploration/stage_tuner.hpp"
#include "tests/conformance/record_difference.hpp"

using namespace swarmcheck;
using namespace swarmcheck::exploration;
using swarmcheck::exploration::testing::first_difference_text;

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededConformanceThreadsTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();


// A map with robots and obstacles on cells drawn without replacement.
Scenario gen_layout() {
  Scenario s = default_scenario();
  s.map_size = *rc::gen::inRange(8, 97);
  const int32_t cells = s.map_size * s.map_size;
  const int32_t robots = *rc::gen::inRange(2, std::max(3, cells * *rc::gen::inRange(1, 40) / 100));
  const int32_t obstacles = *rc::gen::inRange(0, std::max(1, (cells - robots) / 10));
  std::vector<int32_t> order(static_cast<std::size_t>(cells));
  std::iota(order.begin(), order.end(), 0);
  const auto seed = *rc::gen::arbitrary<uint64_t>();
  for (std::size_t k = order.size() - 1; k > 0; --k)   // seeded Fisher-Yates
    std::swap(order[k], order[splitmix64(seed + k) % (k + 1)]);
  s.robots.clear();
  s.obstacles.clear();
  for (int32_t k = 0; k < robots + obstacles; ++k) {
    const int32_t c = order[static_cast<std::size_t>(k)];
    if (k < robots)
      s.robots.push_back({(c / s.map_size + 0.5) * s.cell_size, (c % s.map_size + 0.5) * s.cell_size});
    else
      s.obstacles.push_back({c / s.map_size, c % s.map_size});
  }
  s.params.s_range = *rc::gen::inRange(1, 4);
  s.rule = *rc::gen::element(RuleSet::thesis, RuleSet::deterministic, RuleSet::stochastic);
  s.mode = *rc::gen::element(Mode::abstract, Mode::abstract, Mode::cosim);
  s.seed = *rc::gen::arbitrary<uint64_t>();
  s.max_steps = s.mode == Mode::abstract ? 12 : 60;
  validate(s);
  return s;
}

}  // namespace

RC_GTEST_PROP(Threads, StripPlanningGivesTheOneThreadBitsOnOneTwoFourAndEightThreadsForAnyLayout, ()) {
  const Scenario s = gen_layout();
  ExplorationOptions one;
  one.threads = 1;
  Exploration sequential(s, one);
  std::vector<std::unique_ptr<Exploration>> parallel;
  for (int32_t threads : {1, 2, 4, 8}) {
    ExplorationOptions o;
    o.threads = threads;
    o.parallel_min_robots = 1;   // strips from the second robot on, not only for big steps
    o.parallel_min_bodies = 1;
    parallel.push_back(std::make_unique<Exploration>(s, o));
  }
  while (!sequential.done()) {
    sequential.step();
    for (std::size_t k = 0; k < parallel.size(); ++k) {
      parallel[k]->step();
      const std::string d = first_difference_text(sequential.record(), parallel[k]->record());
      RC_ASSERT(d == "");
    }
  }
}

namespace {

// Robots on every di-th row and dj-th column of an empty n x n map, abstract and stochastic.
Scenario lattice(int32_t n, int32_t di, int32_t dj, int32_t s_range, int64_t steps) {
  Scenario s = default_scenario();
  s.map_size = n;
  s.obstacles.clear();
  s.robots.clear();
  for (int32_t i = 0; i < n; i += di)
    for (int32_t j = 0; j < n; j += dj) s.robots.push_back({i + 0.5, j + 0.5});
  s.params.s_range = s_range;
  s.mode = Mode::abstract;
  s.rule = RuleSet::stochastic;
  s.max_steps = steps;
  return s;
}

// The library with these options and the model agree on every step's record.
void expect_equals_model_step_by_step(const Scenario& s, const ExplorationOptions& options) {
  Exploration a(s, options);
  swarmcheck::model::exploration::ExplorationModel m(s);
  while (!m.done()) {
    a.step();
    m.step();
    ASSERT_EQ(first_difference_text(m.record(), a.record()), "") << a.steps();
  }
}

}  // namespace

TEST(Threads, StripPlanningOfThousandsOfRobotsEqualsTheModel) {
  ExplorationOptions parallel;
  parallel.threads = 4;
  parallel.parallel_min_robots = 1;
  expect_equals_model_step_by_step(lattice(96, 2, 3, 1, 40), parallel);   // 1536 robots
}

// With the default options the Environment times the strips against one thread and runs the
// faster (impl/exploration/stage_tuner.hpp); its first stages alternate between the two, so one
// run mixes both, step by step, and must still be the model's bits.
TEST(Threads, TunedRunsThatMixStripsAndOneThreadStepByStepEqualTheModel) {
  // 704 robots x 7^2 window cells: over the threshold for strips; 70 steps: the trials, then
  // past the first re-probe.
  ExplorationOptions tuned;
  tuned.threads = 4;
  expect_equals_model_step_by_step(lattice(64, 2, 3, 3, 70), tuned);
}

namespace {
using swarmcheck::impl::exploration::StageTuner;

// The modes a tuner asks for over `stages` stages, each taking what `ns` says.
std::string tuner_choices(StageTuner& t, int stages, int64_t parallel_ns, int64_t sequential_ns) {
  std::string out;
  for (int k = 0; k < stages; ++k) {
    const bool p = t.next_parallel();
    out += p ? 'P' : 'S';
    t.record(p, p ? parallel_ns : sequential_ns);
  }
  return out;
}
}  // namespace

// The runs of one mode in a string of choices, e.g. "PPSSP" -> {"PP", "SS", "P"}.
std::vector<std::string> runs_of(const std::string& choices) {
  std::vector<std::string> out;
  for (char c : choices) {
    if (out.empty() || out.back().back() != c) out.emplace_back();
    out.back() += c;
  }
  return out;
}

TEST(StageTuner, AlternatesWarmPairsForItsTrialsThenProbesTheOtherModeAtDoublingIntervals) {
  StageTuner t;
  // Each mode twice in a row: the first of a pair runs cold (after the other mode) and is not timed.
  EXPECT_EQ(tuner_choices(t, 4 * StageTuner::kTrials, 900, 1000), "PPSSPPSSPPSS");
  EXPECT_TRUE(t.decided());
  EXPECT_TRUE(t.faster_is_parallel());
  // Probes of a warm-up and kTrials timed stages (the other mode is not clearly slower here);
  // each that leaves the choice as it was doubles the interval.
  const std::string after = tuner_choices(t, 31 + 4 + 63 + 4 + 127 + 4, 900, 1000);
  std::vector<std::size_t> lengths;
  for (const std::string& r : runs_of(after)) lengths.push_back(r.size());
  EXPECT_EQ(lengths, (std::vector<std::size_t>{31, 4, 63, 4, 127, 4})) << after;
  EXPECT_EQ(after.front(), 'P');
}

TEST(StageTuner, SwitchesToOneThreadWhenTheStripsBecomeSlowerAndBackWhenTheyRecover) {
  StageTuner t;
  tuner_choices(t, 4 * StageTuner::kTrials, 900, 1000);
  ASSERT_TRUE(t.faster_is_parallel());
  // The strips slow down (the machine's other core got busy): seen by the stages that run them.
  const std::string slow = tuner_choices(t, 10, 3000, 1000);
  EXPECT_EQ(slow, "PPPSSSSSSS");
  EXPECT_FALSE(t.faster_is_parallel());
  const std::string settled = tuner_choices(t, 32, 3000, 1000);
  // At most one probe: a warm-up and two clearly slower stages.
  EXPECT_LE(std::count(settled.begin(), settled.end(), 'P'), 3) << settled;
  // They recover: the probes see it (a median needs two of the last three).
  tuner_choices(t, 512, 500, 1000);
  EXPECT_TRUE(t.faster_is_parallel());
}

TEST(StageTuner, EndsItsTrialsAfterOneWarmStageOfEachWhenOneModeIsClearlySlower) {
  StageTuner t;
  EXPECT_EQ(tuner_choices(t, 4, 1'500'000, 1'000'000), "PPSS");   // 10^6 robots: 1.5x
  EXPECT_TRUE(t.decided());
  EXPECT_FALSE(t.faster_is_parallel());
  const std::string after = tuner_choices(t, 34, 1'500'000, 1'000'000);
  // The first probe, at the 32nd chosen stage: a warm-up and two timed stages, both clearly slower.
  EXPECT_EQ(after, std::string(31, 'S') + "PPP");
}

TEST(StageTuner, AProbeThatMeetsOneColdStageStillSeesTheFasterMode) {
  StageTuner t;
  EXPECT_EQ(tuner_choices(t, 4, 1500, 1000), "PPSS");   // the strips looked slower at the start
  ASSERT_FALSE(t.faster_is_parallel());
  tuner_choices(t, 31, 1500, 1000);
  // The probe's warm-up, then one stage whose caches other work emptied, then warm ones: the
  // strips are faster, and the probe says so.
  std::string probe;
  for (const int64_t ns : {600, 5000, 600, 600}) {
    const bool p = t.next_parallel();
    probe += p ? 'P' : 'S';
    t.record(p, ns);
  }
  EXPECT_EQ(probe, "PPPP");
  EXPECT_TRUE(t.faster_is_parallel());
}

TEST(StageTuner, AProbeIsJudgedOnItsOwnFreshTimesNotOnTimesFromBeforeABurstOfNoise) {
  StageTuner t;
  tuner_choices(t, 4 * StageTuner::kTrials, 900, 1000);
  ASSERT_TRUE(t.faster_is_parallel());
  // A burst of noise on the strips: two slow stages make one thread the choice.
  EXPECT_EQ(tuner_choices(t, 3, 5000, 1000), "PPP");
  EXPECT_FALSE(t.faster_is_parallel());
  // The burst is over; the first probe (at the 32nd chosen stage) sees three fresh stages of the
  // strips, all faster, and switches back, although the strips' two slow times are still the
  // last ones it had before.
  const std::string after = tuner_choices(t, 31 + 4 + 1, 900, 1000);
  EXPECT_EQ(after, std::string(31, 'S') + "PPPP" + "P") << after;
  EXPECT_TRUE(t.faster_is_parallel());
}

TEST(StageTuner, OneSlowOutlierDoesNotFlipTheChoice) {
  StageTuner t;
  tuner_choices(t, 4 * StageTuner::kTrials, 900, 1000);
  t.record(true, 1'000'000);   // a warm stage the operating system interrupted
  EXPECT_TRUE(t.faster_is_parallel());
}
