// The handshake obligations: the spec's flag handshake under the Jacobi master (proved by
// k-induction for 1..8 robots), the two orderings under which it breaks (refuted, with a trace
// confirmed by replaying it through the executed code), and the epoch-numbered handshake under
// both (proved). Every obligation first looks for a counterexample from the initial state with
// bounded model checking (no lemma), so a broken rule comes back refuted with a trace, not
// unknown.
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "proofs/obligations/handshake_encoding.hpp"
#include "proofs/obligations/handshake_trace.hpp"
#include "proofs/obligations/obligation.hpp"
#include "spec/exploration/controller.hpp"

namespace swarmcheck::proofs {
namespace {

using namespace handshake;

constexpr int kMaxRobots = 8;
constexpr int kMaxK = 16;
constexpr int kBmcRobots = 3;   // counterexamples of these symmetric protocols need few robots

// How deep the bounded check looks before a lemma is tried. The flag handshake has no counter:
// 6 steps. The epoch handshake's counter wraps every kEpochs epochs, and an epoch takes at least
// 2 steps (plan; accept, arrive and be read) or 4 with late controllers: two full wraps, so that
// a wrap-around bug (a stale epoch read as the new one) is refuted from the initial state.
int bmc_depth(const Variant& v) {
  if (v.protocol == Protocol::flag) return 6;
  const int steps_per_epoch = v.late_controller ? 4 : 2;
  return 2 * exploration::kEpochs * steps_per_epoch + 2;
}

bool value(const z3::model& m, const z3::expr& e) { return m.eval(e, true).is_true(); }

// The model's run, as concrete inputs: the controller parameters, the initial waypoints, and
// each step's poses and issued waypoints.
struct ModelRun {
  exploration::RobotParams rp;
  std::vector<double> wx0, wy0;
  std::vector<std::vector<RobotInput>> inputs;
  std::vector<std::vector<bool>> out_after, driving_after;   // flag protocol: the model's controllers
};

ModelRun run_from_model(Encoding& enc, const z3::model& m, int depth) {
  ModelRun r;
  r.rp.tolerance_m = model_double(m, enc.tolerance());
  r.rp.orient_tolerance_rad = model_double(m, enc.orient_tolerance());
  r.rp.reorient_rad = model_double(m, enc.reorient());
  const Frame& f0 = enc.frame(0);
  for (int i = 0; i < enc.robots(); ++i) {
    r.wx0.push_back(model_double(m, f0.wx[static_cast<std::size_t>(i)]));
    r.wy0.push_back(model_double(m, f0.wy[static_cast<std::size_t>(i)]));
  }
  for (int k = 0; k < depth; ++k) {
    const Step& s = enc.step(k);
    const Frame& nxt = enc.frame(k + 1);
    std::vector<RobotInput> in;
    std::vector<bool> out, drv;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      in.push_back(RobotInput{model_double(m, s.x[i]), model_double(m, s.y[i]), model_double(m, s.theta[i]),
                              model_double(m, s.new_wx[i]), model_double(m, s.new_wy[i])});
      out.push_back(value(m, nxt.out[i]));
      drv.push_back(value(m, nxt.driving[i]));
    }
    r.inputs.push_back(std::move(in));
    r.out_after.push_back(std::move(out));
    r.driving_after.push_back(std::move(drv));
  }
  return r;
}

// Headings to try for a robot, so that the executed controller takes the model's decision: the
// model's own, then the ones that put the bearing error in each class of the controller's
// thresholds (atan2 is uninterpreted in the encoding and the heading enters only through it).
std::vector<double> heading_candidates(const exploration::RobotParams& rp, const RobotInput& in, double wx,
                                       double wy, const exploration::ControllerState& c) {
  // beta = bearing - theta - pi/2 while driving; target - theta while orienting (the target held).
  const double bearing = std::atan2(wy - in.y_m, wx - in.x_m);
  const double zero_beta = c.maneuver == 2 ? bearing - std::numbers::pi / 2 : c.target_theta_rad;
  std::vector<double> out{in.theta_rad};
  for (double beta : {0.0, (rp.orient_tolerance_rad + rp.reorient_rad) / 2, 2 * rp.reorient_rad,
                      std::numbers::pi / 2, std::numbers::pi})
    out.push_back(zero_beta - beta);
  return out;
}

// Replays the model's run through the executed code (handshake_concrete.hpp). Under the flag
// protocol each robot's heading is chosen among heading_candidates so that controller_step takes
// the model's decision; the trace records the run as replayed. Confirmed when the replay plans
// when the model plans and breaks the same property on the same step.
bool replay(const Variant& v, const ModelRun& run, HandshakeTrace& t) {
  ConcreteState s = initial_state(v, t.robots);
  s.x_desired_m = run.wx0;
  s.y_desired_m = run.wy0;
  for (std::size_t k = 0; k < run.inputs.size(); ++k) {
    std::vector<RobotInput> in = run.inputs[k];
    if (v.protocol == Protocol::flag)
      for (std::size_t i = 0; i < in.size(); ++i)
        for (double theta : heading_candidates(run.rp, in[i], s.x_desired_m[i], s.y_desired_m[i], s.ctrl[i])) {
          const exploration::ControllerState n = exploration::controller_step(
              run.rp, s.ctrl[i],
              {{in[i].x_m, in[i].y_m, theta}, {s.x_desired_m[i], s.y_desired_m[i]}, s.env.on_destination_output,
               kHandshakeStep_s});
          if ((n.on_destination_output == 1) == run.out_after[k][i] && (n.maneuver == 2) == run.driving_after[k][i]) {
            in[i].theta_rad = theta;
            break;
          }
        }
    TraceStep& ts = t.steps[k];
    for (std::size_t i = 0; i < in.size(); ++i) {
      TraceController& c = ts.controllers[i];
      c.x_m = in[i].x_m;
      c.y_m = in[i].y_m;
      c.theta_rad = in[i].theta_rad;
      c.x_desired_m = s.x_desired_m[i];
      c.y_desired_m = s.y_desired_m[i];
    }
    const StepEvents ev = step(v, run.rp, s, in);
    if (ev.plan != ts.plan || ev.violated != ts.violated) return false;
  }
  return !t.steps.empty() && !t.steps.back().violated.empty();
}

HandshakeTrace trace_from_model(const std::string& name, Encoding& enc, const z3::model& m, int depth,
                                const exploration::RobotParams& rp) {
  HandshakeTrace t{name, enc.robots(), to_string(enc.variant().master),
                   enc.variant().late_controller ? "late" : "spec", rp.tolerance_m, rp.orient_tolerance_rad,
                   rp.reorient_rad, {}};
  for (int k = 0; k < depth; ++k) {
    const Frame& f = enc.frame(k);
    const Step& s = enc.step(k);
    TraceStep ts{k, value(m, f.flag) ? 1 : 0, value(m, f.eout) ? 1 : 0, value(m, s.plan), {}, ""};
    for (std::size_t i = 0; i < f.out.size(); ++i)
      ts.controllers.push_back(TraceController{value(m, f.port_out[i]) ? 1 : 0, value(m, s.at[i]),
                                               value(m, s.accept[i]), value(m, f.reached[i])});
    if (value(m, s.early_plan)) ts.violated = "no-early-plan";
    else if (value(m, s.stale_accept)) ts.violated = "fresh-acceptance";
    t.steps.push_back(std::move(ts));
  }
  return t;
}

Outcome refuted(const std::string& name, const Variant& v, Encoding& enc, const KInductionResult& r, int n) {
  const ModelRun run = run_from_model(enc, *r.model, r.depth);
  HandshakeTrace t = trace_from_model(name, enc, *r.model, r.depth, run.rp);
  const bool confirmed = replay(v, run, t);
  return {confirmed ? Verdict::refuted : Verdict::unknown,
          fmt::format("sat: with {} robot(s), step {} violates {} ({})", n, r.depth - 1, t.steps.back().violated,
                      confirmed ? "confirmed by replaying the poses through controller_step, all_arrived_rule and "
                                  "the Environment's rule"
                                : "NOT reproduced by the executed code: a spurious counterexample"),
          TraceFile{name + ".jsonl", write_handshake_trace(t)}};
}

Outcome run_handshake(Session& session, const std::string& name, Variant v, bool strengthen) {
  std::string ks;
  // A real run that breaks the property, if any, for every robot count first: a lemma that fails
  // for 1 robot must not hide a run of 2 that the bounded check would have found.
  for (int n = 1; strengthen && n <= kBmcRobots; ++n) {
    Encoding plain(session.ctx(), v, n, false, &session);
    const KInductionResult b = bounded_check(session, plain, bmc_depth(v), fmt::format("n{}", n));
    if (b.verdict == Verdict::refuted) return refuted(name, v, plain, b, n);
    if (b.verdict == Verdict::unknown && session.queries().back().answer != "unsat")
      return {Verdict::unknown, fmt::format("z3 gave up on the bounded check ({} robot(s))", n), {}};
  }
  for (int n = 1; n <= kMaxRobots; ++n) {
    Encoding enc(session.ctx(), v, n, strengthen, &session);
    const KInductionResult r = k_induction(session, enc, kMaxK, fmt::format("n{}", n));
    if (r.verdict == Verdict::refuted && value(*r.model, enc.property(r.depth - 1)))
      return {Verdict::unknown,
              fmt::format("the strengthening lemma is not invariant ({} robot(s), step {}), and no run of up to "
                          "{} steps from the initial state breaks the property",
                          n, r.depth - 1, bmc_depth(v)),
              {}};
    if (r.verdict == Verdict::refuted) return refuted(name, v, enc, r, n);
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
      "robot motion abstracted: each robot's pose (x, y, heading) is free in every step, and a plan "
      "issues each robot a free waypoint; the tolerances are free positive parameters",
      "a step is spec's master_step (its order of reading the controllers and stepping them) on the "
      "spec's rules interpreted over the reals: handshake_stage_rule (environment_handshake_rule) over "
      "all_arrived_rule, the whole controller_rule (arrival, maneuver switch, atan2 fix), or the epoch "
      "rules; atan2 and the angle wrap are uninterpreted with their ranges",
      "no-early-plan is stated over the pose: a robot has reached its waypoint when |x - xDesired| + "
      "|y - yDesired| < tolerance held in some step since the waypoint was issued",
      fmt::format("1..8 robots; k-induction with the simple-path constraint, k <= 16; first bounded model "
                  "checking from the initial state, {} steps, 1..{} robots", bmc_depth(v), kBmcRobots),
      strengthen ? "strengthened by a hand-derived invariant of the reachable states (handshake_encoding.cpp, "
                   "Encoding::lemma), proved together with the property"
                 : "no strengthening lemma: a counterexample is a real run from the initial state",
      "a counterexample counts only when replaying its poses through the executed code (master_step over "
      "controller_step, all_arrived_rule and handshake_stage, or the epoch rules) breaks the same property on "
      "the same step"};
  for (std::string& e : extra) a.push_back(std::move(e));
  std::string n = name;
  return Obligation{std::move(name), std::move(property), expected, std::move(a),
                    [n, v, strengthen](Session& s) { return run_handshake(s, n, v, strengthen); },
                    [v] { return handshake::step_quantities(v); }};
}

}  // namespace

std::vector<Obligation> handshake_obligations() {
  const char* props =
      " the Environment never plans while a robot has not been at its issued waypoint (by its pose, "
      "within the tolerance) since it was issued (no-early-plan), and a controller only accepts a "
      "waypoint issued since its last acceptance (fresh-acceptance).";
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
           {"epoch handshake (spec/exploration/handshake.hpp): the Environment plans when every "
            "controller shows (epoch = its epoch, arrived), then increments its epoch (mod 4); a "
            "controller accepts when it reads an epoch other than the one it last accepted"}),
      make("handshake-epoch-late-controller",
           std::string("With the epoch-numbered handshake under the Jacobi master and late "
                       "controllers,") + props,
           Verdict::proved, Variant{Master::jacobi, Protocol::epoch, true}, true,
           {"epoch handshake as above; late: the Environment reads each controller's output of "
            "two steps before"}),
  };
}

}  // namespace swarmcheck::proofs
