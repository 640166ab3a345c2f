#include "conformance/exploration/conform.hpp"
#include "spec/util/json_text.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "conformance/common/campaign.hpp"
#include "conformance/common/child_process.hpp"
#include "conformance/exploration/trace_io.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::conformance::exploration {

// A child's coverage goes to its parent as JSON (found by ADL: in Coverage's own namespace).
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Coverage, cases_by_family, cases_by_rule_mode, grouped_cases, longest_run_steps,
                                   max_cell_age, cases_age_past_2_12, cases_steps_past_2_15, negative_zero_starts,
                                   off_centre_starts, heading_near_pi_cases, completed_cases, grouped_steps_rows_kept,
                                   grouped_steps_one_row_changed, grouped_steps_rows_exchanged)

namespace {

using nlohmann::json;

json divergence_json(const Divergence& d) {
  return {d.step, d.path, d.model, d.impl, d.spec_violation, d.abnormal_end};
}

Divergence divergence_of(const json& d) {
  Divergence out{d[0].get<int64_t>(), d[1].get<std::string>(), d[2].get<std::string>(), d[3].get<std::string>(),
                 d[4].get<bool>()};
  out.abnormal_end = d[5].get<std::string>();
  return out;
}

std::string text_of(const json& j) { return j.dump(-1, ' ', false, json::error_handler_t::replace); }

// One case's lock-step run where `progress` is (a child process): an exception on either side is a
// divergence too ("impl threw at step 3: ...").
std::optional<Divergence> lockstep(const ExplorationCase& c, LockstepReach& reach, CaseProgress& progress) {
  try {
    return run_lockstep(c.scenario, impl_options(c), &reach, &progress);
  } catch (const std::exception& e) {
    Divergence d{std::max<int64_t>(progress.step(), 0), "", "", "", false};
    d.abnormal_end = thrown_at(progress, e.what()).describe();
    return d;
  }
}

// What a case's child sends back: its divergence and what the run reached.
std::string case_outcome_text(const std::optional<Divergence>& d, const LockstepReach& r) {
  json j{{"reach", {r.steps, r.max_cell_age, r.planning_steps, r.completed, r.heading_near_pi, r.negative_zero_start,
                    r.off_centre_start, r.steps_rows_kept, r.steps_one_row_changed, r.steps_rows_exchanged}}};
  if (d) j["divergence"] = divergence_json(*d);
  return text_of(j);
}

std::optional<Divergence> read_case_outcome(const std::string& text, LockstepReach& r) {
  const json j = swarmcheck::json_io::parse_json_text(text, "the campaign's child process");
  const json& a = j.at("reach");
  r = LockstepReach{a[0].get<int64_t>(), a[1].get<int64_t>(), a[2].get<int64_t>(), a[3].get<bool>(),
                    a[4].get<bool>(), a[5].get<bool>(), a[6].get<bool>(), a[7].get<int64_t>(),
                    a[8].get<int64_t>(), a[9].get<int64_t>()};
  if (!j.contains("divergence")) return std::nullopt;
  return divergence_of(j["divergence"]);
}

// The campaign's report, from the child that ran it to its parent.
std::string report_text(const ConformReport& r) {
  json j{{"cases_run", r.cases_run}, {"coverage", r.coverage}};
  if (const auto& cx = r.counterexample)
    j["counterexample"] = {{"scenario", json_io::to_json(cx->minimal.scenario)},
                           {"family", static_cast<int>(cx->minimal.family)},
                           {"grouped", cx->minimal.grouped},
                           {"divergence", divergence_json(cx->divergence)},
                           {"trace_path", cx->trace_path},
                           {"shrinks", cx->shrinks},
                           {"caught_by", static_cast<int>(cx->caught_by)}};
  return text_of(j);
}

ConformReport read_report(const std::string& text) {
  const json j = swarmcheck::json_io::parse_json_text(text, "the campaign's child process");
  ConformReport r;
  r.cases_run = j.at("cases_run").get<int>();
  r.coverage = j.at("coverage").get<Coverage>();
  if (j.contains("counterexample")) {
    const json& c = j["counterexample"];
    Counterexample cx;
    json_io::from_json(json_io::Json(c.at("scenario")), "scenario", cx.minimal.scenario);
    cx.minimal.family = static_cast<Family>(c.at("family").get<int>());
    cx.minimal.grouped = c.at("grouped").get<bool>();
    cx.divergence = divergence_of(c.at("divergence"));
    cx.trace_path = c.at("trace_path").get<std::string>();
    cx.shrinks = c.at("shrinks").get<int>();
    cx.caught_by = static_cast<Family>(c.at("caught_by").get<int>());
    r.counterexample = cx;
  }
  return r;
}

void note_coverage(const ExplorationCase& c, const LockstepReach& r, Coverage& cov) {
  ++cov.cases_by_family[std::string(family_name(c.family))];
  ++cov.cases_by_rule_mode[json_io::enum_to_string(c.scenario.rule) + "/" + json_io::enum_to_string(c.scenario.mode)];
  cov.grouped_cases += c.grouped ? 1 : 0;
  cov.longest_run_steps = std::max(cov.longest_run_steps, r.steps);
  cov.max_cell_age = std::max(cov.max_cell_age, r.max_cell_age);
  cov.cases_age_past_2_12 += r.max_cell_age >= 4096 ? 1 : 0;
  cov.cases_steps_past_2_15 += r.steps >= 32768 ? 1 : 0;
  cov.negative_zero_starts += r.negative_zero_start ? 1 : 0;
  cov.off_centre_starts += r.off_centre_start ? 1 : 0;
  cov.heading_near_pi_cases += r.heading_near_pi ? 1 : 0;
  cov.completed_cases += r.completed ? 1 : 0;
  if (c.grouped) {
    cov.grouped_steps_rows_kept += r.steps_rows_kept;
    cov.grouped_steps_one_row_changed += r.steps_one_row_changed;
    cov.grouped_steps_rows_exchanged += r.steps_rows_exchanged;
  }
}

// The campaign, its cases run where `here` is (in this process, itself a child: the first pass),
// or, without it, each in a child process of its own (the second pass), which does not run again
// the first `skip` cases (the first pass saw them agree).
ConformReport run_cases(const ConformOptions& o, CaseProgress* here, int64_t skip) {
  ConformReport report;
  // The last failing run is the shrunk one: RapidCheck only continues from failing shrinks.
  std::optional<std::pair<ExplorationCase, Divergence>> last_failure;
  int64_t first_cases = 0;   // cases drawn before the first failure
  const auto property = [&](CaseBudget& budget) {
    const ExplorationCase c = *gen_exploration_case(o.max_steps);
    if (!last_failure && ++first_cases <= skip) return;
    LockstepReach reach;
    bool hung = false;
    std::optional<Divergence> d;
    if (here) {
      here->alive();
      d = lockstep(c, reach, *here);
    } else {
      d = run_case_isolated(c, o.quiet_limit, &reach, &hung);
    }
    if (hung) budget.hung();
    if (!report.counterexample && (!d || d->abnormal_end.empty())) note_coverage(c, reach, report.coverage);
    if (here && !d && !last_failure) here->agreed(first_cases);
    if (d) {
      last_failure.emplace(c, *d);
      if (!report.counterexample) {
        report.counterexample.emplace();
        report.counterexample->caught_by = c.family;
      }
    }
    RC_ASSERT(!d.has_value());
  };
  const CampaignRun run = run_campaign("exploration: impl equals model bit for bit", o.seed, o.cases, property,
                                      o.on_case, ShrinkBudget{});
  report.cases_run = run.cases_run;
  if (!last_failure) {
    report.counterexample.reset();
    return report;
  }
  Counterexample& cx = *report.counterexample;
  cx.shrinks = run.shrinks;
  cx.minimal = last_failure->first;
  cx.divergence = last_failure->second;
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) throw InputError(o.out_dir, "cannot create the output folder: " + ec.message());
  cx.trace_path = (std::filesystem::path(o.out_dir) /
                   ("counterexample-seed" + std::to_string(o.seed) + ".jsonl")).string();
  write_counterexample(cx.trace_path, cx.minimal, cx.divergence);
  return report;
}

}  // namespace

std::optional<Divergence> run_case_isolated(const ExplorationCase& c, std::chrono::milliseconds quiet_limit,
                                            LockstepReach* reach, bool* hung) {
  const ChildEnd end = run_in_child([&](CaseProgress& p) {
    LockstepReach r;
    const auto d = lockstep(c, r, p);
    return case_outcome_text(d, r);
  }, ChildLimits{quiet_limit});
  if (hung) *hung = end.how == ChildEnd::How::hung;
  LockstepReach r;
  if (end.finished()) {
    const auto d = read_case_outcome(end.output, r);
    if (reach) *reach = r;
    return d;
  }
  Divergence d{std::max<int64_t>(end.step, 0), "", "", "", false};
  d.abnormal_end = end.describe();
  return d;
}

ConformReport run_conform(const ConformOptions& o) {
  if (o.cases < 1) throw InputError("--cases", "expected an integer >= 1");
  if (o.max_steps < 1) throw InputError("--max-steps", "expected an integer >= 1");
  // First the whole campaign in one child; if the library crashed or hung in it, again with each
  // case in a child of its own, so that the case that crashes shrinks like any other.
  const FirstPass first = run_campaign_in_child([&](CaseProgress& p) { return report_text(run_cases(o, &p, 0)); },
                                                ChildLimits{o.quiet_limit});
  if (first.report) return read_report(*first.report);
  return run_cases(o, nullptr, first.cases_agreed);
}

}  // namespace swarmcheck::conformance::exploration
