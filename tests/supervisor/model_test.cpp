// The reference model on hand-checked examples, and the spec's defining properties of its
// results on random automata (supervisor controllable, nonblocking, inside the specification).
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "model/supervisor/operations.hpp"
#include "spec/supervisor/semantics.hpp"
#include "spec/util/input_error.hpp"

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededSupervisorModelTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using namespace swarmcheck::model::supervisor;
namespace model = swarmcheck::model::supervisor;
using swarmcheck::conformance::supervisor::Alphabet;
using swarmcheck::conformance::supervisor::gen_alphabet;
using swarmcheck::conformance::supervisor::gen_automaton;
using swarmcheck::impl::supervisor::read_fsm;

// Two machines and a one-slot buffer between them (Wonham's small factory): a = start
// (controllable), b = finish (uncontrollable); the spec forbids buffer overflow and underflow.
const char* kMachine1 = "2\nI1 1 1\na1 W1 c o\nW1 0 1\nb1 I1 uc o\n";
const char* kMachine2 = "2\nI2 1 1\na2 W2 c o\nW2 0 1\nb2 I2 uc o\n";
const char* kBuffer = "2\nB0 1 1\nb1 B1 uc o\nB1 0 1\na2 B0 c o\n";

TEST(SupervisorModel, SmallFactorySupervisorKeepsSixStates) {
  const Automaton plant = model::product({read_fsm(kMachine1, "m1"), read_fsm(kMachine2, "m2")},
                                  {"m1", "m2"});
  const Automaton spec = read_fsm(kBuffer, "buffer");
  EXPECT_EQ(plant.states.size(), 4u);
  EXPECT_FALSE(model::is_controllable(plant, spec));  // starting M1 with a full buffer overflows it
  const Automaton sup = model::supcon(plant, spec);
  EXPECT_EQ(sup.states.size(), 6u);
  EXPECT_EQ(sup.states.front(), "I1.I2.B0");
  EXPECT_EQ(sup.delta.at("I1.I2.B1").count("a1"), 0u);  // a1 disabled while the buffer is full
  EXPECT_TRUE(model::is_controllable(plant, sup));
  EXPECT_TRUE(model::is_nonblocking(sup));
}

TEST(SupervisorModel, BlockingAndUnreachableStates) {
  const Automaton a = read_fsm("4\ns 0 2\na m\nb d\nm 1 0\nd 0 0\nu 0 1\na s\n", "t");
  EXPECT_EQ(model::accessible_states(a), (StateSet{"s", "m", "d"}));
  EXPECT_EQ(model::coaccessible_states(a), (StateSet{"s", "m", "u"}));
  EXPECT_EQ(model::blocking_states(a), (std::vector<State>{"d"}));
  EXPECT_EQ(model::trim(a).states, (std::vector<State>{"s", "m"}));
  EXPECT_FALSE(model::is_nonblocking(a));
}

TEST(SupervisorModel, EmptySupervisorWhenUncontrollableEventLeadsToBlocking) {
  // The plant can always do u (uncontrollable) into a dead end the spec forbids.
  const Automaton plant = read_fsm("2\np 1 1\nu q uc o\nq 0 0\n", "plant");
  const Automaton spec = read_fsm("1\ns 1 0\nEVENTS\nu uc o\n", "spec");
  EXPECT_TRUE(model::supcon(plant, spec).states.empty());
}

TEST(SupervisorModel, AttributeConflictInProductIsAnInputError) {
  const Automaton a = read_fsm("1\nx 1 1\ne x c o\n", "a.fsm");
  const Automaton b = read_fsm("1\ny 1 1\ne y uc o\n", "b.fsm");
  try {
    model::product({a, b}, {"a.fsm", "b.fsm"});
    FAIL() << "no error";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "b.fsm: event 'e' is uncontrollable and observable here but controllable and "
                 "observable in a.fsm");
  }
}

TEST(SupervisorModel, LanguageInclusionWitnesses) {
  const Automaton ab = read_fsm("3\n0 0 1\na 1\n1 0 1\nb 2\n2 1 0\n", "ab");
  const Automaton a_only = read_fsm("2\n0 0 1\na 1\n1 1 0\n", "a");
  const Inclusion i = model::language_inclusion(ab, a_only);
  EXPECT_FALSE(i.closed);
  EXPECT_EQ(i.closed_witness, (std::vector<Event>{"a", "b"}));
  EXPECT_FALSE(i.marked);
  const Inclusion j = model::language_inclusion(a_only, ab);
  EXPECT_TRUE(j.closed);
  EXPECT_FALSE(j.marked);
  EXPECT_EQ(j.marked_witness, (std::vector<Event>{"a"}));
}

RC_GTEST_PROP(SupervisorModel, SupervisorIsControllableNonblockingAndInsideTheSpec, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton plant = *gen_automaton(alphabet, {20, 70, 30});
  const Automaton spec = *gen_automaton(alphabet, {10, 90, 50});
  const Automaton sup = model::supcon(plant, spec);
  RC_ASSERT(model::is_nonblocking(sup));
  RC_ASSERT(model::is_controllable(plant, sup));
  const Automaton both = model::product({plant, spec}, {"plant", "spec"});
  const Inclusion in = model::language_inclusion(sup, both);
  RC_ASSERT(in.closed);
  RC_ASSERT(in.marked);
}

RC_GTEST_PROP(SupervisorModel, ProductLanguageIsTheIntersectionOnASharedAlphabet, ()) {
  Alphabet alphabet = *gen_alphabet();
  const Automaton a = *gen_automaton(alphabet, {15, 60, 30});
  Automaton b = *gen_automaton(alphabet, {15, 60, 30});
  b.events = a.events;  // same alphabet: || is intersection of languages
  for (auto& [q, row] : b.delta)
    for (auto it = row.begin(); it != row.end();) it = a.events.count(it->first) ? ++it : row.erase(it);
  const Automaton p = model::product({a, b}, {"a", "b"});
  const auto word = *rc::gen::container<std::vector<std::string>>(
      rc::gen::elementOf(std::vector<std::string>{"e0", "e1", "e2", "e3"}));
  RC_ASSERT(in_closed_language(p, word) ==
            (in_closed_language(a, word) && in_closed_language(b, word)));
  RC_ASSERT(in_marked_language(p, word) ==
            (in_marked_language(a, word) && in_marked_language(b, word)));
}

}  // namespace
