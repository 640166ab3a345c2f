// `fsm controllable`'s checks (spec/supervisor/control.hpp): impl against model on generated
// plants and supervisors, witnesses replayed on the automata, hand-made cases, and the thesis's
// control2.fsm against the plant built from its components.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/control.hpp"

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededSupervisorControlTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using namespace swarmcheck::conformance::supervisor;
namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
namespace sv = swarmcheck::supervisor;
using Words = std::vector<std::string>;

const std::string kThesis = SWARMCHECK_SCENARIOS "/thesis/";

// What a report claims, checked on the automata themselves: the controllability witness replays
// as a violation, every shorter word of the closed loop is no violation, and the blocking
// witness leads to a closed-loop state that cannot reach a marked state.
void check_witnesses(const Automaton& plant, const Automaton& sup, const sv::ControlReport& r) {
  const model::Product loop = model::product2(plant, "plant", sup, "supervisor");
  if (!r.controllable) {
    RC_ASSERT(sv::is_uncontrollability_witness(plant, sup, r.witness, r.disabled_event));
    RC_ASSERT(!plant.events.at(r.disabled_event).controllable);
  } else {
    RC_ASSERT(model::is_controllable(plant, sup));
  }
  if (!r.nonblocking) {
    const auto at = sv::closed_loop_run(plant, sup, r.blocking_witness);
    RC_ASSERT(at.has_value());
    RC_ASSERT(!model::coaccessible_states(loop.automaton).count(sv::pair_name(at->first, at->second)));
  } else {
    RC_ASSERT(model::is_nonblocking(loop.automaton));
  }
}

RC_GTEST_PROP(SupervisorControl, ImplReportEqualsModelReportOnGeneratedPlantsAndSupervisors, ()) {
  const Alphabet alphabet = *gen_alphabet();
  std::vector<Automaton> plant_parts{*gen_automaton(alphabet, {30, 70, 30})};
  if (*rc::gen::arbitrary<bool>()) plant_parts.push_back(*gen_automaton(alphabet, {8, 70, 50}));
  const Automaton sup = *gen_automaton(alphabet, {12, 80, 40});
  const auto d = diff_control(plant_parts, sup);
  RC_ASSERT(!d.has_value());
}

RC_GTEST_PROP(SupervisorControl, EveryWitnessReplaysAndIsShortest, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton plant = *gen_automaton(alphabet, {20, 70, 30});
  const Automaton sup = *gen_automaton(alphabet, {10, 80, 40});
  const sv::ControlReport r = model::control_report(plant, sup);
  check_witnesses(plant, sup, r);
  if (!r.controllable) {
    // No shorter word of the closed loop is a witness (breadth first over words of length < |w|).
    std::vector<Words> layer{{}};
    for (std::size_t len = 0; len < r.witness.size(); ++len) {
      std::vector<Words> next;
      for (const auto& w : layer) {
        const auto at = sv::closed_loop_run(plant, sup, w);
        RC_ASSERT(at.has_value());
        RC_ASSERT(sv::uncontrollable_disabled(plant, sup, at->first, at->second).empty());
        for (const auto& [e, attr] : alphabet) {
          auto longer = w;
          longer.push_back(e);
          if (sv::closed_loop_run(plant, sup, longer)) next.push_back(longer);
        }
      }
      layer = std::move(next);
    }
  }
}

Automaton parse(const std::string& text) { return impl::read_fsm(text, "t.fsm"); }

TEST(SupervisorControl, ShortestWitnessAndLeastEventOnAHandMadePlant) {
  // The plant does a (c) then u or v (both uc); the supervisor allows a, then only u... after b.
  const Automaton plant = parse("3\np0 0 2\na p1 c o\nb p1 c o\np1 0 2\nu p2 uc o\nv p2 uc o\np2 1 0\n");
  const Automaton sup = parse("4\ns0 0 2\na s1 c o\nb s2 c o\ns1 0 0\ns2 0 1\nu s3 uc o\ns3 1 0\nEVENTS\nv uc o\n");
  for (const auto& r : {model::control_report(plant, sup),
                        impl::control_report(impl::compile(plant), impl::compile(sup))}) {
    EXPECT_FALSE(r.controllable);
    EXPECT_EQ(r.witness, Words{"a"});
    EXPECT_EQ(r.disabled_event, "u");   // u and v are both disabled after a: the least name
    EXPECT_FALSE(r.nonblocking);        // after a nothing can happen, and s1 is not marked
    EXPECT_EQ(r.blocking_witness, Words{"a"});
    EXPECT_EQ(r.closed_loop_states, 4u);
  }
}

TEST(SupervisorControl, AnEventOutsideTheSupervisorIsNeverDisabled) {
  const Automaton plant = parse("2\np0 0 1\nu p1 uc o\np1 1 0\n");
  const Automaton sup = parse("1\ns0 1 0\n");
  const sv::ControlReport r = model::control_report(plant, sup);
  EXPECT_TRUE(r.controllable);
  EXPECT_TRUE(r.nonblocking);
  EXPECT_EQ(r, impl::control_report(impl::compile(plant), impl::compile(sup)));
}

// The thesis's hand-made supervisor against the plant of both robots (the four plant components
// of scenarios/thesis/components, as `fsm synth` takes them).
TEST(SupervisorControl, ThesisControl2AgainstThePlantOfTheComponents) {
  std::vector<std::string> files;
  for (const char* f : {"region_a.fsm", "tasks_a.fsm", "region_b.fsm", "tasks_b.fsm"})
    files.push_back(kThesis + "components/" + f);
  files.push_back(kThesis + "control2.fsm");
  std::vector<Automaton> all = sv::read_fsm_files(files);
  const Automaton control2 = all.back();
  all.pop_back();
  ASSERT_FALSE(diff_control(all, control2).has_value());
  const Automaton plant = model::product(all, {"region_a", "tasks_a", "region_b", "tasks_b"});
  const sv::ControlReport r = model::control_report(plant, control2);
  // control2.fsm never names b3s (nor b4s, a8e, b6e): as a supervisor it lets robot B start task 3,
  // and then disables B's uncontrollable entry into region 7 on the way there.
  EXPECT_EQ(r.closed_loop_states, 187u);
  EXPECT_FALSE(r.controllable);
  EXPECT_EQ(r.witness, (Words{"b8e", "b3s"}));
  EXPECT_EQ(r.disabled_event, "b7e");
  EXPECT_FALSE(control2.events.count("b3s"));
  EXPECT_TRUE(sv::is_uncontrollability_witness(plant, control2, r.witness, r.disabled_event));
  // The replay by hand: both automata follow the word, the plant enables b7e, control2 does not.
  const auto at = sv::closed_loop_run(plant, control2, r.witness);
  ASSERT_TRUE(at.has_value());
  EXPECT_TRUE(sv::successor(plant, at->first, "b7e").has_value());
  EXPECT_FALSE(sv::successor(control2, at->second, "b7e").has_value());
  EXPECT_EQ(at->second, "s3");   // control2 after b8e (b3s is not its event)
  // The same state blocks: B, stopped before region 7, can never finish.
  EXPECT_FALSE(r.nonblocking);
  EXPECT_EQ(r.blocking_witness, (Words{"b8e", "b3s"}));
}

}  // namespace
