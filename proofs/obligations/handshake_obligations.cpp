// The handshake obligations: the spec's flag handshake under the Jacobi master (proved by
// k-induction for 1..8 robots), the two orderings under which it breaks (refuted, with a trace
// confirmed by replaying it through the spec's functions), and the epoch-numbered handshake
// under both (proved).
#include <fmt/format.h>

#include "proofs/obligations/handshake_encoding.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "proofs/obligations/obligation.hpp"

namespace swarmcheck::proofs {
namespace {

using namespace handshake;

constexpr int kMaxRobots = 8;
constexpr int kMaxK = 16;

bool value(const z3::model& m, const z3::expr& e) { return m.eval(e, true).is_true(); }

HandshakeTrace trace_from_model(const std::string& name, Encoding& enc, const z3::model& m, int depth) {
  HandshakeTrace t{name, enc.robots(), to_string(enc.variant().master),
                   enc.variant().late_controller ? "late" : "spec", {}};
  for (int k = 0; k < depth; ++k) {
    const Frame& f = enc.frame(k);
    const Step& s = enc.step(k);
    TraceStep ts{k, value(m, f.flag) ? 1 : 0, value(m, f.eout) ? 1 : 0, value(m, s.plan), {}, ""};
    for (std::size_t i = 0; i < f.out.size(); ++i)
      ts.controllers.push_back(TraceController{value(m, f.port_out[i]) ? 1 : 0, value(m, s.arrival[i]),
                                               value(m, s.accept[i]), value(m, f.reached[i])});
    if (value(m, s.early_plan)) ts.violated = "no-early-plan";
    else if (value(m, s.stale_accept)) ts.violated = "fresh-acceptance";
    t.steps.push_back(std::move(ts));
  }
  return t;
}

// Replays the trace's arrivals through the concrete handshake (environment_handshake and
// controller_step): the same plans, and the same violation on the same step?
bool replays(const Variant& v, const HandshakeTrace& t) {
  ConcreteState s = initial_state(v, t.robots);
  for (const TraceStep& ts : t.steps) {
    std::vector<bool> arrival;
    for (const TraceController& c : ts.controllers) arrival.push_back(c.arrival);
    const StepEvents ev = step(v, s, arrival);
    if (ev.plan != ts.plan || ev.violated != ts.violated) return false;
  }
  return !t.steps.empty() && !t.steps.back().violated.empty();
}

Outcome run(Session& session, const std::string& name, Variant v, bool strengthen) {
  std::string ks;
  for (int n = 1; n <= kMaxRobots; ++n) {
    Encoding enc(session.ctx(), v, n, strengthen);
    const KInductionResult r = k_induction(session, enc, kMaxK, fmt::format("n{}", n));
    if (r.verdict == Verdict::refuted && value(*r.model, enc.property(r.depth - 1)))
      return {Verdict::unknown,
              fmt::format("the strengthening lemma is not invariant ({} robot(s), step {})", n, r.depth - 1), {}};
    if (r.verdict == Verdict::refuted) {
      const HandshakeTrace t = trace_from_model(name, enc, *r.model, r.depth);
      const bool confirmed = replays(v, t);
      return {Verdict::refuted,
              fmt::format("sat: with {} robot(s), step {} violates {} ({})", n, r.depth - 1,
                          t.steps.back().violated,
                          confirmed ? "confirmed by replaying the arrivals through environment_handshake "
                                      "and controller_step"
                                    : "NOT reproduced by the concrete replay"),
              TraceFile{name + ".jsonl", write_handshake_trace(t)}};
    }
    if (r.verdict == Verdict::unknown)
      return {Verdict::unknown, fmt::format("k-induction did not close for {} robot(s) within k = {}", n, kMaxK), {}};
    ks += fmt::format("{}{}", ks.empty() ? "" : ", ", r.k);
  }
  return {Verdict::proved,
          fmt::format("unsat: k-induction closed for 1..{} robots at k = {}", kMaxRobots, ks), {}};
}

Obligation make(std::string name, std::string property, Verdict expected, Variant v,
                bool strengthen, std::vector<std::string> extra) {
  std::vector<std::string> a = {
      "robot motion abstracted: each robot's arrival is a free boolean per step (any sequence a "
      "body could produce, and more)",
      "the Environment side is environment_handshake tabulated over (flag, onDestinationOutput, "
      "all_arrived); the controller side is controller_step's onDestinationOutput tabulated over "
      "(output, input, robot on its waypoint)",
      "1..8 robots; k-induction with the simple-path constraint, k <= 16",
      strengthen ? "strengthened by a hand-derived invariant of the reachable states (handshake_encoding.cpp, "
                   "Encoding::lemma), proved together with the property"
                 : "no strengthening lemma: a counterexample is a real run from the initial state",
      "no two robots sent to one cell and no waypoint on an obstacle follow from occupancy (the "
      "Environment's cells are the robots' issued waypoints, which they have reached whenever it "
      "plans): this obligation proves that premise (no-early-plan)"};
  for (std::string& e : extra) a.push_back(std::move(e));
  std::string n = name;
  return Obligation{std::move(name), std::move(property), expected, std::move(a),
                    [n, v, strengthen](Session& s) { return run(s, n, v, strengthen); }};
}

}  // namespace

std::vector<Obligation> handshake_obligations() {
  const char* props =
      " the Environment never plans while a robot has not reached its issued waypoint "
      "(no-early-plan), and a controller only accepts a waypoint issued since its last acceptance "
      "(fresh-acceptance).";
  return {
      make("handshake-safety", std::string("Under the Jacobi master with the spec's controller side,") + props,
           Verdict::proved, Variant{Master::jacobi, Protocol::flag, false}, true,
           {"Jacobi: every component reads the outputs of the previous step"}),
      make("handshake-gauss-seidel",
           std::string("Under a Gauss-Seidel master (Environment stepped after the controllers "
                       "within a step),") + props,
           Verdict::refuted, Variant{Master::gauss_seidel, Protocol::flag, false}, false,
           {"Gauss-Seidel: controllers read the Environment's previous outputs, the Environment "
            "reads the controllers' new ones"}),
      make("handshake-late-controller",
           std::string("Under the Jacobi master with a controller whose output reaches the "
                       "Environment one step late,") + props,
           Verdict::refuted, Variant{Master::jacobi, Protocol::flag, true}, false,
           {"late: the Environment reads each controller's output of two steps before"}),
      make("handshake-epoch-gauss-seidel",
           std::string("With the epoch-numbered handshake under the Gauss-Seidel master,") + props,
           Verdict::proved, Variant{Master::gauss_seidel, Protocol::epoch, false}, true,
           {"epoch handshake: the Environment plans when every controller shows (epoch = its "
            "epoch, arrived), then increments its epoch (mod 4); a controller accepts when it "
            "reads an epoch other than the one it last accepted"}),
      make("handshake-epoch-late-controller",
           std::string("With the epoch-numbered handshake under the Jacobi master and late "
                       "controllers,") + props,
           Verdict::proved, Variant{Master::jacobi, Protocol::epoch, true}, true,
           {"epoch handshake as above; late: the Environment reads each controller's output of "
            "two steps before"}),
  };
}

}  // namespace swarmcheck::proofs
