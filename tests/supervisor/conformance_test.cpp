// The conformance campaign of the automata operations: impl/supervisor against model/supervisor
// on generated automata, every operation, seeded (conformance/supervisor/campaign.hpp); the
// exact comparison; and the canary that shows the harness can fail.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "conformance/supervisor/campaign.hpp"
#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededSupervisorConformanceTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using namespace swarmcheck::conformance::supervisor;
namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;

// The default budget and seed, as `swarmcheck conform` runs them: the same cases on every run.
TEST(SupervisorConformance, ImplEqualsModelExactlyOnEveryOperationOfTheSeededCampaign) {
  CampaignOptions o;
  o.out_dir = (std::filesystem::temp_directory_path() / ("swarmcheck-automata-" + std::to_string(::getpid()))).string();
  const CampaignReport r = run_campaign(o);
  ASSERT_FALSE(r.counterexample.has_value()) << r.counterexample->difference << "\n" << r.counterexample->command;
  EXPECT_EQ(r.cases_run, o.cases);
  for (const char* kind : {"unary", "product", "big", "synthesis", "big_synth", "inclusion", "roundtrip",
                           "control", "observation"})
    EXPECT_GT(r.coverage.cases_by_kind.count(kind), 0u) << kind;
  EXPECT_GE(r.coverage.largest_product_states, 1000u);   // the growth paths ran
  EXPECT_GT(r.coverage.inclusions_failing, 0);           // witnesses were compared
  std::filesystem::remove_all(o.out_dir);
}

// A library that gave two states one name would agree with the model up to renaming (and a
// name-keyed copy would merge them); the exact comparison must call it a difference.
TEST(SupervisorConformance, ADuplicateStateNameIsADifference) {
  Automaton a;
  a.states = {"x", "y"};
  a.events["e"] = swarmcheck::supervisor::EventAttr{true, true};
  a.delta["x"]["e"] = "y";
  impl::Fsm f = impl::compile(a);
  f.state_names[1] = "x";
  const auto d = diff_exact("test", f, a);
  ASSERT_TRUE(d.has_value());
  EXPECT_NE(d->find("duplicate"), std::string::npos) << *d;
}

// The canary: a deliberately wrong supervisor (forgets uncontrollability: trim of the product)
// must be told apart from the model's, or the harness could not catch anything.
TEST(SupervisorConformance, CanaryWrongSupervisorIsCaught) {
  const bool passed = rc::check("canary: trim(plant || spec) as the supervisor", [] {
    const Alphabet alphabet = *gen_alphabet();
    const Automaton plant = *gen_automaton(alphabet, {12, 70, 30});
    const Automaton spec = *gen_automaton(alphabet, {6, 90, 50});
    const Automaton wrong = model::trim(model::product({plant, spec}, {"plant", "spec"}));
    RC_ASSERT(canonical(wrong) == canonical(model::supcon(plant, spec)));
  });
  EXPECT_FALSE(passed) << "the harness did not catch a supervisor that ignores controllability";
}

}  // namespace
