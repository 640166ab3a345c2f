// The thesis example rebuilt from its parts (scenarios/thesis/components, see generate.py and
// docs/supervisor.md): the supervisor is synthesised by impl and model alike, is controllable
// and nonblocking, equals the committed supervisor files, and differs from control2.fsm exactly
// where the documented choices say it does.
#include <gtest/gtest.h>

#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/engine.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"

namespace {

namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
using swarmcheck::supervisor::Automaton;
using Words = std::vector<std::string>;

const std::string kDir = SWARMCHECK_SCENARIOS "/thesis/";

// Inclusion by the library, checked equal to the model's (verdicts and witnesses).
swarmcheck::supervisor::Inclusion inclusion(const Automaton& a, const Automaton& b) {
  namespace engines = swarmcheck::conformance::supervisor;
  const auto lib = engines::language_inclusion(a, b, engines::Engine::impl);
  EXPECT_EQ(lib, engines::language_inclusion(a, b, engines::Engine::model));
  return lib;
}

Automaton compose(const std::vector<std::string>& files) {
  std::vector<Automaton> parts;
  for (const auto& f : files) parts.push_back(impl::read_fsm_file(kDir + "components/" + f));
  return model::product(parts, files);
}

Automaton plant() {
  return compose({"region_a.fsm", "tasks_a.fsm", "region_b.fsm", "tasks_b.fsm"});
}

Automaton synthesise(const std::string& completion) {
  const Automaton g = plant();
  const Automaton s = compose({"avoidance.fsm", "located.fsm", completion});
  const Automaton sup = model::supcon(g, s);
  EXPECT_EQ(swarmcheck::conformance::supervisor::canonical(sup),
            swarmcheck::conformance::supervisor::canonical(
                impl::decompile(impl::supcon(impl::compile(g), impl::compile(s)))));
  EXPECT_TRUE(model::is_nonblocking(sup));
  EXPECT_TRUE(model::is_controllable(g, sup));
  return sup;
}

TEST(ThesisExample, PlantOfBothRobots) { EXPECT_EQ(plant().states.size(), 1848u); }

TEST(ThesisExample, SupervisorWithTheOtherRobotRule) {
  const Automaton sup = synthesise("completion.fsm");
  EXPECT_EQ(sup.states.size(), 37u);
  EXPECT_EQ(sup.marked.size(), 1u);
  EXPECT_EQ(impl::write_fsm(sup), impl::write_fsm(impl::read_fsm_file(kDir + "supervisor.fsm")));
  // Only A on 3-4 and B on 1-2 can avoid each other: A's route to task 2 crosses region 6 where
  // B would end task 4, and B's route to task 3 crosses region 7 where A would end task 2.
  const auto in = inclusion(sup, impl::read_fsm_file(kDir + "control2.fsm"));
  EXPECT_FALSE(in.closed);
  EXPECT_EQ(in.closed_witness, (Words{"a5e", "b8e", "a3s", "a6e", "a3f", "a4s", "a4f"}));
}

TEST(ThesisExample, SupervisorWhereOneRobotMayDoBothPairs) {
  const Automaton sup = synthesise("completion_any_robot.fsm");
  EXPECT_EQ(sup.states.size(), 75u);
  EXPECT_EQ(impl::write_fsm(sup),
            impl::write_fsm(impl::read_fsm_file(kDir + "supervisor_any_robot.fsm")));
  const Automaton control2 = impl::read_fsm_file(kDir + "control2.fsm");
  // The one difference both ways: for task 4 right after task 3 (both in region 6), control2
  // makes robot A leave region 6 and come back (a5e a6e) before a4f; our routes stay put.
  const auto ours_in_theirs = inclusion(sup, control2);
  EXPECT_EQ(ours_in_theirs.closed_witness,
            (Words{"a5e", "b8e", "a3s", "a6e", "a3f", "a4s", "a4f"}));
  const auto theirs_in_ours = inclusion(control2, sup);
  EXPECT_EQ(theirs_in_ours.closed_witness,
            (Words{"a5e", "b8e", "a3s", "a6e", "a3f", "a4s", "a5e"}));
}

}  // namespace
