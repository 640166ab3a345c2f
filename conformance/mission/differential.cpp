#include "conformance/mission/differential.hpp"

#include <bit>
#include <cstdint>

#include <boost/hana.hpp>

#include "model/mission/brute_force.hpp"
#include "model/mission/run_model.hpp"
#include "spec/util/hana_diff.hpp"
#include "swarmcheck/mission.hpp"

namespace swarmcheck::conformance::mission {

namespace {

namespace sm = swarmcheck::mission;

// Everything a run shows: its result and every record its observer saw, in order.
struct Observed {
  BOOST_HANA_DEFINE_STRUCT(Observed,
      (sm::RunResult, result),
      (std::vector<sm::EventRecord>, events),
      (std::vector<sm::StepRecord>, steps),
      (std::vector<sm::IntervalRecord>, intervals));
};

class Recorder final : public sm::RunObserver {
 public:
  Recorder(Observed& out, CaseProgress* progress, CaseProgress::Side side)
      : out_(out), progress_(progress), side_(side) {
    if (progress_) progress_->at(0, side_);
  }
  void on_event(const sm::EventRecord& e) override { out_.events.push_back(e); }
  void on_step(const sm::StepRecord& s) override {
    out_.steps.push_back(s);
    // Records 0..k seen: step k + 1 is being computed.
    if (progress_) progress_->at(static_cast<int64_t>(out_.steps.size()), side_);
  }
  void on_interval(const sm::IntervalRecord& i) override { out_.intervals.push_back(i); }

 private:
  Observed& out_;
  CaseProgress* progress_;
  CaseProgress::Side side_;
};

std::string cost_text(const sm::Plan& p) {
  return p.found ? json_io::value_text(p.cost.makespan) + " / " + json_io::value_text(p.cost.total)
                 : "no plan";
}

}  // namespace

std::optional<std::string> diff_run(const sm::Mission& m, const sm::RunOptions& o,
                                    const PlanFunction& model_plan, CaseProgress* progress) {
  Observed lib, model;
  Recorder lib_recorder(lib, progress, CaseProgress::Side::impl);
  lib.result = sm::run_mission(m, o, &lib_recorder);
  Recorder model_recorder(model, progress, CaseProgress::Side::model);
  sm::Planner planner(m);
  const PlanFunction exact = [&](const sm::PlanQuery& q) { return planner.plan(q); };
  model.result = swarmcheck::model::mission::run_model(m, o, model_plan ? model_plan : exact,
                                                       &model_recorder);
  const auto d = json_io::first_difference(lib, model);
  if (!d) return std::nullopt;
  return d->path + ": impl " + d->a + ", model " + d->b;
}

std::optional<std::string> diff_plan(const sm::Mission& m, const sm::PlanQuery& q, CaseProgress* progress) {
  if (progress) progress->at(-1, CaseProgress::Side::impl);
  const sm::Plan exact = sm::Planner(m).plan(q);
  if (progress) progress->at(-1, CaseProgress::Side::model);
  const sm::Plan brute = swarmcheck::model::mission::brute_force_plan(m, q);
  if (progress) progress->at(-1, CaseProgress::Side::none);
  // The objective is (makespan, total), compared by bits. Among plans of equal objective the
  // per-robot travel may differ (two robots swapping tasks): each planner's own order decides
  // (spec/mission/plan.hpp), and the stream kind compares whole plans of one planner.
  const auto same_bits = [](double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); };
  if (exact.found != brute.found ||
      (exact.found && !(same_bits(exact.cost.makespan, brute.cost.makespan) && same_bits(exact.cost.total, brute.cost.total))))
    return "plan cost (makespan / total): impl " + cost_text(exact) + ", model " + cost_text(brute);
  if (!exact.found) return std::nullopt;
  const sm::PathEvaluation ev = sm::evaluate_path(m, q, exact.events);
  if (!ev.error.empty()) return "the exact plan is not a plan: " + ev.error;
  if (ev.final_state != exact.final_state || !(ev.cost == exact.cost))
    return "the exact plan states another cost or final state than its path has";
  return std::nullopt;
}

}  // namespace swarmcheck::conformance::mission
