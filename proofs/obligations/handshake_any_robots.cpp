// The handshake for every number of robots: the Environment's loops over the controllers
// (handshake_lemmas.hpp), and the epoch handshake by a representative robot: robot 0 stands for
// any one robot, robot 1 for all the others (its state and port free in every step). The
// Environment's plan is then any value that robot 0's readiness allows (the loop lemma: the plan
// of n ports is robot 0's readiness and the others'), which every run of any number of robots
// projects onto; robot 0's part of the hand-derived lemma and its two properties are proved by
// k-induction on that system, after a bounded check two epoch wraps deep.
#include <fmt/format.h>

#include <cstdint>
#include <memory>

#include "proofs/obligations/handshake_encoding.hpp"
#include "proofs/obligations/handshake_lemmas.hpp"
#include "proofs/obligations/handshake_system.hpp"
#include "proofs/obligations/kinduction.hpp"
#include "proofs/obligations/translate.hpp"
#include "spec/exploration/handshake.hpp"
#include "spec/exploration/master.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

using S = num::Symbolic;
using C = num::Concrete;
constexpr int kBoundedControllers = 8;

}  // namespace

std::optional<Outcome> all_arrived_lemma(Session& session) {
  z3::context& c = session.ctx();
  // Bounded: the master's reading of n controllers.
  for (int n = 0; n <= kBoundedControllers; ++n) {
    Translator t(session, RealTheory::real);
    std::vector<sym::Bool> outputs;
    z3::expr every = c.bool_val(true);
    for (int k = 0; k < n; ++k) {
      outputs.push_back(sym::Bool::var(fmt::format("output_{}", k)));
      every = every && t(outputs.back());
    }
    const z3::expr all = t(exploration::environment_input(std::span<const sym::Bool>(outputs)));
    z3::solver s = session.make_solver();
    s.add(all != every);
    const std::string label = fmt::format("all-arrived-n{}", n);
    const z3::check_result r = session.check(s, label);
    if (r == z3::unsat) continue;
    if (r != z3::sat) return Outcome{Verdict::unknown, "unknown on query " + label, {}};
    const z3::model m = s.get_model();
    std::vector<bool> out;
    bool conj = true;
    for (const sym::Bool& o : outputs) {
      out.push_back(m.eval(t(o), true).is_true());
      conj = conj && out.back();
    }
    const bool got = exploration::all_arrived_rule<C>(out.size(), [&](std::size_t k) { return out[k]; });
    std::string shown;
    for (bool o : out) shown += o ? '1' : '0';
    return Outcome{got != conj ? Verdict::refuted : Verdict::unknown,
                   fmt::format("sat: {}: {} controller(s) with onDestinationOutput {}: all_arrived gives {} ({})", label,
                               n, shown, got,
                               got != conj ? "confirmed by running all_arrived_rule"
                                           : "NOT reproduced by the executed code: a spurious counterexample"),
                   {}};
  }
  // Every n: the loop's body keeps `all` equal to "no lowered output so far".
  Translator t(session, RealTheory::real);
  const sym::Bool all = sym::Bool::var("all"), output = sym::Bool::var("output");
  const z3::expr lowered = c.int_const("lowered");
  const z3::expr next = t(num::traced("exploration::all_arrived_rule", exploration::all_arrived_step_rule<S>(all, output)));
  z3::solver s = session.make_solver();
  s.add(lowered >= 0 && t(all) == (lowered == 0));
  s.add(next != (lowered + z3::ite(t(output), c.int_val(0), c.int_val(1)) == 0));
  const z3::check_result r = session.check(s, "all-arrived-step");
  if (r == z3::unsat) return std::nullopt;
  if (r != z3::sat) return Outcome{Verdict::unknown, "unknown on query all-arrived-step", {}};
  // A prefix with (lowered > 0 ? one : no) lowered output, then the model's output.
  const z3::model m = s.get_model();
  std::vector<bool> out;
  if (m.eval(lowered, true).get_numeral_int64() > 0) out.push_back(false);
  out.push_back(m.eval(t(output), true).is_true());
  bool conj = true;
  for (bool o : out) conj = conj && o;
  const bool got = exploration::all_arrived_rule<C>(out.size(), [&](std::size_t k) { return out[k]; });
  return Outcome{got != conj ? Verdict::refuted : Verdict::unknown,
                 fmt::format("sat: all-arrived-step: the loop's body breaks \"true iff no output is lowered\"; {} "
                             "controller(s): all_arrived gives {} ({})",
                             out.size(), got,
                             got != conj ? "confirmed by running all_arrived_rule"
                                         : "NOT reproduced by the executed code: a spurious counterexample"),
                 {}};
}

std::optional<Outcome> epoch_ready_lemma(Session& session) {
  z3::context& c = session.ctx();
  for (int n = 0; n <= kBoundedControllers; ++n) {
    Translator t(session, RealTheory::real);
    const sym::Int epoch = sym::Int::var("epoch");
    std::vector<sym::Int> acks;
    std::vector<sym::Bool> done;
    std::vector<z3::expr> ready;
    for (int k = 0; k < n; ++k) {
      acks.push_back(sym::Int::var(fmt::format("ack_{}", k)));
      done.push_back(sym::Bool::var(fmt::format("done_{}", k)));
      ready.push_back(t(acks.back()) == t(epoch) && t(done.back()));
    }
    const exploration::EpochStepT<S> e = exploration::epoch_environment_rule<S>(epoch, acks, done);
    z3::expr every = c.bool_val(true);
    for (const z3::expr& r : ready) every = every && r;
    // The property: plans iff every port shows (epoch, arrived); then the epoch advances by one
    // mod kEpochs, else it stays.
    const z3::expr advanced = z3::mod(t(epoch) + 1, exploration::kEpochs);
    z3::solver s = session.make_solver();
    s.add(t(epoch) >= 0 && t(epoch) < exploration::kEpochs);
    s.add(!(t(e.plan) == every && t(e.epoch) == z3::ite(every, advanced, t(epoch))));
    const std::string label = fmt::format("epoch-ready-n{}", n);
    const z3::check_result r = session.check(s, label);
    if (r == z3::unsat) continue;
    if (r != z3::sat) return Outcome{Verdict::unknown, "unknown on query " + label, {}};
    const z3::model m = s.get_model();
    const int32_t ep = static_cast<int32_t>(m.eval(t(epoch), true).get_numeral_int64());
    std::vector<int32_t> a;
    const std::unique_ptr<bool[]> d(new bool[static_cast<std::size_t>(n) + 1]);
    bool all = true;
    for (int k = 0; k < n; ++k) {
      a.push_back(static_cast<int32_t>(m.eval(t(acks[static_cast<std::size_t>(k)]), true).get_numeral_int64()));
      d[static_cast<std::size_t>(k)] = m.eval(t(done[static_cast<std::size_t>(k)]), true).is_true();
      all = all && a.back() == ep && d[static_cast<std::size_t>(k)];
    }
    const exploration::EpochStepT<C> got =
        exploration::epoch_environment_rule<C>(ep, a, std::span<const bool>(d.get(), static_cast<std::size_t>(n)));
    const bool confirmed = got.plan != all || got.epoch != (all ? (ep + 1) % exploration::kEpochs : ep);
    return Outcome{confirmed ? Verdict::refuted : Verdict::unknown,
                   fmt::format("sat: {}: epoch {}, {} port(s): epoch_environment_rule plans {} and moves to epoch {} ({})",
                               label, ep, n, got.plan, got.epoch,
                               confirmed ? "confirmed by running epoch_environment_rule"
                                         : "NOT reproduced by the executed code: a spurious counterexample"),
                   {}};
  }
  Translator t(session, RealTheory::real);
  const sym::Bool ready = sym::Bool::var("ready"), done = sym::Bool::var("done");
  const sym::Int epoch = sym::Int::var("epoch"), ack = sym::Int::var("ack");
  const z3::expr waiting = c.int_const("waiting");
  const z3::expr next = t(num::traced("exploration::epoch_environment_rule",
                                      exploration::epoch_ready_step_rule<S>(ready, epoch, ack, done)));
  z3::solver s = session.make_solver();
  s.add(waiting >= 0 && t(ready) == (waiting == 0));
  s.add(next != (waiting + z3::ite(t(ack) == t(epoch) && t(done), c.int_val(0), c.int_val(1)) == 0));
  const z3::check_result r = session.check(s, "epoch-ready-step");
  if (r == z3::unsat) return std::nullopt;
  return Outcome{r == z3::sat ? Verdict::refuted : Verdict::unknown,
                 r == z3::sat ? "sat: epoch-ready-step: the loop's body breaks \"ready iff no port is waiting\" "
                                "(confirmed: the body is a function of its arguments alone)"
                              : "unknown on query epoch-ready-step",
                 {}};
}

namespace {

constexpr int kRepresentativeMaxK = 8;

Outcome run_epoch_any(Session& session, Variant v) {
  if (auto o = epoch_ready_lemma(session)) return *o;
  v.representative = true;
  const int depth = 2 * exploration::kEpochs * (v.late_controller ? 4 : 2) + 2;
  {
    Encoding plain(session.ctx(), v, 2, false, &session);
    const KInductionResult b = bounded_check(session, plain, depth, "representative");
    if (b.verdict == Verdict::refuted)
      return {Verdict::unknown,
              fmt::format("sat at step {} of the representative system (robot 1 standing for every other robot, free): "
                          "the property fails for some number of robots (handshake-epoch-* give concrete traces)",
                          b.depth - 1),
              {}};
    if (session.queries().back().answer != "unsat")
      return {Verdict::unknown, "z3 gave up on the bounded check of the representative system", {}};
  }
  Encoding enc(session.ctx(), v, 2, true, &session);
  const KInductionResult r = k_induction(session, enc, kRepresentativeMaxK, "representative");
  if (r.verdict == Verdict::proved)
    return {Verdict::proved,
            fmt::format("unsat: the epoch loop for every number of ports; robot 0's lemma and properties against any "
                        "other robots, k-induction closed at k = {}: every number of robots",
                        r.k),
            {}};
  if (r.verdict == Verdict::refuted)
    return {Verdict::unknown,
            fmt::format("sat at depth {} of the representative system: robot 0's lemma or property is not inductive "
                        "against free other robots",
                        r.depth),
            {}};
  return {Verdict::unknown, fmt::format("k-induction on the representative system: no verdict within k = {}", kRepresentativeMaxK), {}};
}

}  // namespace

}  // namespace swarmcheck::proofs::handshake

namespace swarmcheck::proofs {

std::vector<Obligation> handshake_any_robots_obligations() {
  using handshake::Master;
  using handshake::Protocol;
  using handshake::Variant;
  const char* props =
      " no-early-plan and fresh-acceptance hold for every number of robots: the Environment never plans while a robot "
      "has not been at its issued waypoint since it was issued, and a controller only accepts a waypoint issued since "
      "its last acceptance.";
  const std::vector<std::string> common = {
      "the Environment's loop over the ports (epoch_environment_rule): plans iff every port shows (its epoch, "
      "arrived), then the epoch advances by one mod 4; for 0..8 ports bounded, for every number by induction over "
      "the loop's body (epoch_ready_step_rule)",
      "a representative robot: robot 0 stands for any one robot, robot 1 for all the others, its state and port free "
      "in every step; every run of any number of robots projects onto this system (the plan is robot 0's readiness "
      "and the others'), so robot 0's properties hold for every robot of every run",
      "a step is spec's master_step on epoch_controller_rule with arrived_rule and epoch_environment_rule over the "
      "reals; motion abstracted (poses free every step, a plan issues free waypoints), tolerance free and positive",
      "a bounded check two epoch wraps deep, then k-induction (k <= 8) with robot 0's part of the hand-derived lemma; "
      "a counterexample of this abstraction is reported unknown (handshake-epoch-* give concrete traces)"};
  auto make = [&](std::string name, std::string property, Variant v) {
    std::vector<std::string> a = common;
    return Obligation{std::move(name), std::move(property), Verdict::proved, a,
                      [v](Session& s) { return handshake::run_epoch_any(s, v); },
                      [v] { return handshake::step_quantities(v); }};
  };
  return {
      Obligation{"all-arrived-any-robots",
                 "The Environment's input as the master reads it (environment_input: all_arrived_rule of the "
                 "controllers' onDestinationOutput) is true iff every controller's output is raised, for every number "
                 "of controllers.",
                 Verdict::proved,
                 {"bounded for 0..8 controllers, each output a free boolean, through master_step's environment_input",
                  "for every number of controllers by induction over all_arrived_rule's loop: its body "
                  "(all_arrived_step_rule) keeps \"true iff no output lowered so far\"; the loop runs it over k = 0..n-1 "
                  "(the bounded part checks that shape)",
                  "a counterexample counts only when all_arrived_rule, run on its outputs, gives the wrong answer"},
                 [](Session& s) -> Outcome {
                   if (auto o = handshake::all_arrived_lemma(s)) return *o;
                   return {Verdict::proved,
                           fmt::format("unsat: 0..8 controllers, and the loop's body for every number; {} queries",
                                       s.queries().size()),
                           {}};
                 },
                 [] {
                   std::vector<sym::Bool> outputs{sym::Bool::var("output_0"), sym::Bool::var("output_1")};
                   return std::vector<sym::NodePtr>{
                       exploration::environment_input(std::span<const sym::Bool>(outputs)).node()};
                 }},
      make("handshake-epoch-any-robots",
           std::string("With the epoch-numbered handshake under the Gauss-Seidel master,") + props,
           Variant{Master::gauss_seidel, Protocol::epoch, false}),
      make("handshake-epoch-late-any-robots",
           std::string("With the epoch-numbered handshake under the Jacobi master and late controllers,") + props,
           Variant{Master::jacobi, Protocol::epoch, true}),
  };
}

}  // namespace swarmcheck::proofs
