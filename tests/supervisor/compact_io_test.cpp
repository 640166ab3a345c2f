// The compact paths the command line takes on large automata: the .fsm reader and writer on Fsm
// (no Automaton value), products and supervisors whose states are spelled only when written.
// Each must give exactly what the value-based path gives: the same bytes, names and errors.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_compact_io.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"
#include "spec/util/input_error.hpp"

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededSupervisorCompactIoTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using namespace swarmcheck::conformance::supervisor;
namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;

std::string compact_text(const impl::Fsm& f, const impl::TupleNames* names = nullptr) {
  return impl::write_fsm_compact(f, impl::name_speller(f, names));
}

std::string error_of(const std::string& text) {
  try {
    impl::read_fsm_compact(text, "t.fsm");
  } catch (const swarmcheck::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

// States renamed so that product names can stand for two pairs: the left automaton's state i is
// "p<i/2>" or "p<i/2>.m", the right's "s<i/2>" or "m.s<i/2>", so (p0, m.s1) and (p0.m, s1) are
// both named "p0.m.s1".
// With `private_events`, the right one's events are renamed apart: its product with the left is
// then every pair of reachable states, and names meet far more often.
Automaton with_dotted_names(const Automaton& a, bool left, bool private_events = false) {
  std::map<std::string, std::string> rename;
  for (std::size_t i = 0; i < a.states.size(); ++i) {
    const std::string half = std::to_string(i / 2);
    rename[a.states[i]] = left ? "p" + half + (i % 2 ? ".m" : "") : (i % 2 ? "m.s" : "s") + half;
  }
  auto event = [&](const std::string& e) { return private_events ? "r" + e : e; };
  Automaton out;
  for (const auto& [e, attr] : a.events) out.events[event(e)] = attr;
  for (const auto& q : a.states) out.states.push_back(rename[q]);
  for (const auto& q : a.marked) out.marked.insert(rename[q]);
  for (const auto& [q, row] : a.delta)
    for (const auto& [e, t] : row) out.delta[rename[q]][event(e)] = rename[t];
  return out;
}

RC_GTEST_PROP(CompactFsmIo, WritingTheCompactFormGivesTheBytesWriteFsmGives, ()) {
  const Automaton a = *gen_automaton(*gen_alphabet(), {30, 50, 30});
  RC_ASSERT(compact_text(impl::compile(a)) == impl::write_fsm(a));
}

RC_GTEST_PROP(CompactFsmIo, ReadingTheWrittenTextGivesBackTheSameAutomaton, ()) {
  const Automaton a = *gen_automaton(*gen_alphabet(), {30, 50, 30});
  RC_ASSERT(impl::decompile(impl::read_fsm_compact(impl::write_fsm(a), "t.fsm")) == a);
}

RC_GTEST_PROP(CompactFsmIo, AProductSpelledFromItsTuplesIsTheNamedProductByteForByte, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton a = *gen_automaton(alphabet, {20, 60, 40});
  const Automaton b = *gen_automaton(alphabet, {20, 60, 40});
  const impl::Fsm fa = impl::compile(a), fb = impl::compile(b);
  const impl::Product lazy = impl::product_with_tuples({&fa, &fb}, {"a", "b"});
  const impl::Fsm named = impl::product({&fa, &fb}, {"a", "b"});
  RC_ASSERT(lazy.fsm.state_names.empty() || lazy.fsm.state_count() == 0);
  RC_ASSERT(compact_text(lazy.fsm, &lazy.names) == impl::write_fsm(impl::decompile(named)));
}

// The name check hashes spellings instead of storing them: it must refuse exactly the products
// the model refuses, with the same message, and accept the rest.
RC_GTEST_PROP(CompactFsmIo, ProductNamesThatStandForTwoPairsAreRefusedAsTheModelRefusesThem, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton a = with_dotted_names(*gen_automaton(alphabet, {16, 90, 40}), true);
  const Automaton b = with_dotted_names(*gen_automaton(alphabet, {16, 90, 40}), false,
                                       *rc::gen::arbitrary<bool>());
  // The state names in order, or the error: names only, as a duplicate name is not writable.
  auto outcome = [](auto&& states) -> std::string {
    try {
      std::string out;
      for (const auto& q : states()) out += q + "\n";
      return out;
    } catch (const swarmcheck::InputError& e) {
      return std::string("error: ") + e.what();
    }
  };
  const impl::Fsm fa = impl::compile(a), fb = impl::compile(b);
  const std::string lazy = outcome([&] {
    const impl::Product p = impl::product_with_tuples({&fa, &fb}, {"a", "b"});
    std::vector<std::string> names;
    for (impl::StateId z = 0; z < p.fsm.state_count(); ++z) names.push_back(p.names.name(z));
    return names;
  });
  RC_CLASSIFY(lazy.rfind("error: ", 0) == 0, "refused");  // both outcomes must occur
  RC_ASSERT(lazy == outcome([&] { return model::product({a, b}, {"a", "b"}).states; }));
}

RC_GTEST_PROP(CompactFsmIo, SynthesisSpelledFromPairsIsSupconAndKnowsWhetherTheSpecIsControllable, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton plant = *gen_automaton(alphabet, {12, 70, 30});
  const Automaton spec = *gen_automaton(alphabet, {6, 90, 50});
  const impl::Fsm fp = impl::compile(plant), fs = impl::compile(spec);
  const impl::Synthesis s = impl::synthesize(fp, fs);
  RC_ASSERT(s.spec_controllable == model::is_controllable(plant, spec));
  RC_ASSERT(compact_text(s.supervisor, &s.names) == impl::write_fsm(model::supcon(plant, spec)));
}

TEST(CompactFsmRead, TheFirstUndefinedTargetInReadingOrderIsReportedNotTheFirstName) {
  // 'late' is named first but defined later; 'b' and 'a' are never defined: 'b' comes first.
  EXPECT_EQ(error_of("2\ns 0 3\nx late\ny b\nz a\nlate 0 1\nw a\n"),
            "t.fsm:4:3: transition target 'b' of state 's' is not a state (no block of that name "
            "in this file)");
}

TEST(CompactFsmRead, NondeterminismNamesTheLineOfTheEarlierTransitionInALargeBlock) {
  std::string text = "1\ns 0 202\n";
  for (int i = 0; i < 200; ++i) text += "e" + std::to_string(i) + " s\n";
  text += "e7 s\n";   // repeated: the same meaning, dropped
  text += "e9 t\n";   // e9 was first at line 12
  EXPECT_EQ(error_of(text), "t.fsm:204:4: nondeterministic state 's': event 'e9' leads to 's' "
                            "(line 12) and to 't'");
}

TEST(CompactFsmRead, AByteErrorLateInTheFileComesBeforeAStructuralErrorEarlier) {
  EXPECT_EQ(error_of("x\ns 0 0\n\x01"), "t.fsm:3:1: unexpected control character (byte 1)");
}

TEST(CompactFsmRead, StatesKeepFileOrderAndEventsAreNumberedInNameOrder) {
  const impl::Fsm f = impl::read_fsm_compact("2\nb 1 2\nz a uc\nm b\na 0 0\n", "t.fsm");
  EXPECT_EQ(f.state_names, (std::vector<std::string>{"b", "a"}));
  EXPECT_EQ(f.event_names, (std::vector<std::string>{"m", "z"}));
  EXPECT_EQ(f.edge_event, (std::vector<impl::EventId>{0, 1}));
  EXPECT_EQ(f.edge_target, (std::vector<impl::StateId>{0, 1}));
  EXPECT_EQ(f.controllable, (std::vector<std::uint8_t>{1, 0}));
}

}  // namespace
