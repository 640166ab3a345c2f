// Partial observation (spec/supervisor/observation.hpp): the observer, the observability check
// and the supremal controllable normal supervisor, impl against model on generated automata,
// and each checked against its definition on the automata themselves.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <deque>

#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/observation.hpp"
#include "swarmcheck/supervisor.hpp"

// Counterexamples shown as .fsm text.
namespace swarmcheck::supervisor {
inline void showValue(const Automaton& a, std::ostream& os) { os << "\n" << write_fsm(a); }
inline void showValue(const EventAttr& a, std::ostream& os) {
  os << (a.controllable ? "c" : "uc") << " " << (a.observable ? "o" : "uo");
}
}  // namespace swarmcheck::supervisor

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededSupervisorObservationTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

using namespace swarmcheck::conformance::supervisor;
namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;
namespace sv = swarmcheck::supervisor;
using Words = std::vector<std::string>;

// The states of a that words with projection v reach: a search over (state, letters of v read).
sv::StateSet reached_by_projection(const Automaton& a, const Words& v) {
  std::set<std::pair<sv::State, std::size_t>> seen{{a.states.front(), 0}};
  std::deque<std::pair<sv::State, std::size_t>> queue(seen.begin(), seen.end());
  sv::StateSet out;
  while (!queue.empty()) {
    const auto [q, i] = queue.front();
    queue.pop_front();
    if (i == v.size()) out.insert(q);
    for (const auto& e : sv::enabled(a, q)) {
      const bool obs = a.events.at(e).observable;
      if (obs && (i == v.size() || v[i] != e)) continue;
      const std::pair<sv::State, std::size_t> next{*sv::successor(a, q, e), obs ? i + 1 : i};
      if (seen.insert(next).second) queue.push_back(next);
    }
  }
  return out;
}

RC_GTEST_PROP(SupervisorObservation, ImplObserverEqualsModelObserverExactly, ()) {
  const Automaton a = *gen_automaton(*gen_alphabet(), {40, 50, 30});
  const auto d = diff_observer(a);
  RC_ASSERT(!d.has_value());
}

// Every observer state reached by an observable word v is exactly the set of states the words
// with projection v reach, and it is marked iff one of them is.
RC_GTEST_PROP(SupervisorObservation, EachObserverStateIsTheSetOfStatesReachedByItsProjection, ()) {
  const Automaton a = *gen_automaton(*gen_alphabet(), {15, 50, 30});
  const Automaton obs = model::observer(a);
  RC_ASSERT(obs.states.size() >= 1u);
  std::map<sv::State, Words> word{{obs.states.front(), {}}};
  std::deque<sv::State> queue{obs.states.front()};
  while (!queue.empty()) {
    const sv::State x = queue.front();
    queue.pop_front();
    const sv::StateSet members = reached_by_projection(a, word.at(x));
    RC_ASSERT(sv::subset_name(a, members) == x);
    bool marked = false;
    for (const auto& q : members) marked = marked || a.marked.count(q) > 0;
    RC_ASSERT(marked == (obs.marked.count(x) > 0));
    for (const auto& [e, attr] : a.events) {
      const auto t = sv::successor(obs, x, e);
      RC_ASSERT(t.has_value() == (attr.observable && !sv::post_event(a, members, e).empty()));
      if (t && !word.count(*t)) {
        auto longer = word.at(x);
        longer.push_back(e);
        word.emplace(*t, longer);
        queue.push_back(*t);
      }
    }
  }
}

RC_GTEST_PROP(SupervisorObservation, ImplObservabilityEqualsModelAndItsWitnessReplays, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton plant = *gen_automaton(alphabet, {15, 70, 30});
  const Automaton spec = *gen_automaton(alphabet, {8, 80, 40});
  const auto d = diff_observability({plant}, spec);
  RC_ASSERT(!d.has_value());
  const auto r = model::observability(plant, spec);
  if (!r.observable) RC_ASSERT(sv::is_unobservability_witness(plant, spec, r));
}

// A specification: random, or (more often, and so more often a nonempty supervisor) the plant
// with some transitions taken out.
Automaton gen_spec(const Alphabet& alphabet, const Automaton& plant) {
  if (*chance(30)) return *gen_automaton(alphabet, {10, 90, 60});
  Automaton spec = plant;
  for (auto& [q, row] : spec.delta)
    for (auto it = row.begin(); it != row.end();) it = *chance(12) ? row.erase(it) : std::next(it);
  return spec;
}

RC_GTEST_PROP(SupervisorObservation, ImplNormalSupervisorEqualsModelExactly, ()) {
  const Alphabet alphabet = *gen_alphabet();
  std::vector<Automaton> plant_parts{*gen_automaton(alphabet, {30, 70, 50})};
  if (*rc::gen::arbitrary<bool>()) plant_parts.push_back(*gen_automaton(alphabet, {6, 70, 50}));
  const Automaton spec = gen_spec(alphabet, plant_parts.front());
  BuiltSizes sizes;
  const auto d = diff_supcon_normal(plant_parts, spec, &sizes);
  RC_ASSERT(!d.has_value());
  bool unobservable = false;
  for (const auto& [e, attr] : alphabet) unobservable = unobservable || !attr.observable;
  RC_TAG(unobservable ? "with uo events" : "all observable",
         sizes.supervisor_states == 0 ? "empty supervisor" : "nonempty supervisor");
}

// s in L(R) and s' in L(G) with P(s) = P(s') imply s' in L(R): a search over (state of R after
// s, state of G after s', state of R after s' or none), moving on one projection. s' is a word
// of the plant: it has no event the plant does not have (SPEC.md 13.3).
bool is_normal(const Automaton& g, const Automaton& r) {
  if (r.states.empty()) return true;
  using Node = std::tuple<sv::State, sv::State, std::optional<sv::State>>;
  std::set<Node> seen;
  std::deque<Node> queue;
  auto visit = [&](const Node& n) {
    if (seen.insert(n).second) queue.push_back(n);
  };
  visit({r.states.front(), g.states.front(), r.states.front()});
  while (!queue.empty()) {
    const auto [p, x, q] = queue.front();
    queue.pop_front();
    if (!q) return false;
    for (const auto& [e, attr] : r.events) {
      const auto p2 = sv::successor(r, p, e);
      const auto x2 = g.events.count(e) ? sv::successor(g, x, e) : std::nullopt;
      const auto q2 = sv::successor(r, *q, e);
      if (attr.observable) {
        if (p2 && x2) visit({*p2, *x2, q2});
        continue;
      }
      if (p2) visit({*p2, x, q});
      if (x2) visit({p, *x2, q2});
    }
  }
  return true;
}

// The result is what it claims: controllable, normal (so observable), nonblocking, and inside
// the supremal controllable supervisor (which ignores observation).
RC_GTEST_PROP(SupervisorObservation, NormalSupervisorIsControllableNormalNonblockingAndWithinSupcon, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton plant = *gen_automaton(alphabet, {20, 70, 50});
  const Automaton spec = gen_spec(alphabet, plant);
  const Automaton r = model::supcon_normal(plant, spec);
  RC_TAG(r.states.empty() ? "empty supervisor" : "nonempty supervisor");
  RC_ASSERT(model::is_controllable(plant, r));
  RC_ASSERT(model::is_nonblocking(r));
  RC_ASSERT(is_normal(plant, r));
  RC_ASSERT(model::observability(plant, r).observable);
  const auto in = model::language_inclusion(r, model::supcon(plant, spec));
  RC_ASSERT(in.closed);
  RC_ASSERT(in.marked);
}

// The canary: supcon, which sees every event, is not normal in general, and the checker above
// must say so, or the property before could not fail.
TEST(SupervisorObservation, CanarySupconIgnoringObservationIsCaughtAsNotNormal) {
  const bool passed = rc::check("canary: supcon as the normal supervisor", [] {
    const Alphabet alphabet = *gen_alphabet();
    const Automaton plant = *gen_automaton(alphabet, {20, 70, 50});
    RC_ASSERT(is_normal(plant, model::supcon(plant, gen_spec(alphabet, plant))));
  });
  EXPECT_FALSE(passed) << "the normality check did not catch a supervisor that sees uo events";
}

RC_GTEST_PROP(SupervisorObservation, WithEveryEventObservableTheNormalSupervisorIsSupcon, ()) {
  Alphabet alphabet = *gen_alphabet();
  for (auto& [e, attr] : alphabet) attr.observable = true;
  const Automaton plant = *gen_automaton(alphabet, {20, 70, 30});
  const Automaton spec = *gen_automaton(alphabet, {8, 90, 60});
  const Automaton normal = model::supcon_normal(plant, spec);
  const Automaton sup = model::supcon(plant, spec);
  RC_ASSERT(model::language_inclusion(normal, sup) == sv::Inclusion{});
  RC_ASSERT(model::language_inclusion(sup, normal) == sv::Inclusion{});
}

Automaton parse(const std::string& text) { return impl::read_fsm(text, "t.fsm"); }

// The plant may do an unobservable fault f before a; the specification forbids a after f only.
// A supervisor that cannot see f must forbid a always; supcon, which sees everything, does not.
TEST(SupervisorObservation, AnUnseenFaultForcesTheSupervisorToDisableWhatItForbidsAfterIt) {
  const Automaton plant = parse(
      "4\np0 1 2\nf p1 uc uo\na p2 c o\np1 1 1\na p3 c o\np2 1 0\np3 1 0\n");
  const Automaton spec = parse("3\ns0 1 2\nf s1 uc uo\na s2 c o\ns1 1 0\ns2 1 0\n");
  const Automaton normal = model::supcon_normal(plant, spec);
  EXPECT_FALSE(diff_supcon_normal({plant}, spec).has_value());
  EXPECT_EQ(normal.states, (Words{"p0.s0.o0", "p1.s1.o0"}));
  EXPECT_TRUE(sv::enabled(normal, "p0.s0.o0") == Words{"f"});
  EXPECT_EQ(model::supcon(plant, spec).states.size(), 3u);   // p0.s0, p1.s1, p2.s2: a allowed first
  const auto r = model::observability(plant, spec);
  EXPECT_FALSE(r.observable);
  EXPECT_EQ(r.word, Words{});
  EXPECT_EQ(r.twin, Words{"f"});
  EXPECT_EQ(r.event, "a");
  EXPECT_EQ(r, impl::observability(impl::compile(plant), impl::compile(spec)));
  const Automaton obs = model::observer(plant);
  EXPECT_EQ(obs.states, (Words{"{p0,p1}", "{p2,p3}"}));
  EXPECT_EQ(impl::write_fsm(obs), impl::write_fsm(impl::decompile(impl::observer(impl::compile(plant)))));
}

// The thesis's plant and specification with region entries made unobservable: impl and model
// agree state for state; unseen b7e changes nothing (37 states, as with full observation); with
// no region entry seen, collision avoidance cannot be enforced and the supervisor is empty.
TEST(SupervisorObservation, ThesisWithUnseenRegionEntries) {
  const std::string dir = SWARMCHECK_SCENARIOS "/thesis/components/";
  std::vector<std::string> files;
  for (const char* f : {"region_a", "tasks_a", "region_b", "tasks_b", "avoidance", "located", "completion"})
    files.push_back(dir + f + ".fsm");
  const std::vector<Automaton> all = sv::read_fsm_files(files);
  auto hidden = [&](const std::set<std::string>& unseen) {
    std::map<sv::Event, sv::EventAttr> attrs;
    for (const auto& a : all)
      for (auto [e, attr] : a.events) attrs[e] = {attr.controllable, !unseen.count(e)};
    std::vector<Automaton> parts;
    for (const auto& a : all) parts.push_back(sv::with_attributes(a, attrs));
    const Automaton spec = model::product({parts[4], parts[5], parts[6]}, {"avoidance", "located", "completion"});
    parts.resize(4);
    EXPECT_FALSE(diff_supcon_normal(parts, spec).has_value());
    const Automaton plant = model::product(parts, {"region_a", "tasks_a", "region_b", "tasks_b"});
    return std::make_pair(plant, model::supcon_normal(plant, spec));
  };
  const auto [plant, one] = hidden({"b7e"});
  EXPECT_EQ(one.states.size(), 37u);
  EXPECT_TRUE(model::is_controllable(plant, one));
  EXPECT_TRUE(is_normal(plant, one));
  EXPECT_TRUE(hidden({"a5e", "a6e", "a7e", "a8e", "b5e", "b6e", "b7e", "b8e"}).second.states.empty());
}

TEST(SupervisorObservation, AStateNameWithACommaIsRefusedByTheObserver) {
  const Automaton a = parse("1\na,b 0 0\n");
  EXPECT_THROW(model::observer(a), swarmcheck::InputError);
  EXPECT_THROW(impl::observer(impl::compile(a)), swarmcheck::InputError);
}

}  // namespace
