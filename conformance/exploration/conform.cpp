#include "conformance/exploration/conform.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <filesystem>

#include "conformance/common/campaign.hpp"
#include "conformance/exploration/trace_io.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::conformance::exploration {
namespace {

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
}

}  // namespace

ConformReport run_conform(const ConformOptions& o) {
  if (o.cases < 1) throw InputError("--cases", "expected an integer >= 1");
  if (o.max_steps < 1) throw InputError("--max-steps", "expected an integer >= 1");
  ConformReport report;
  // The last failing run is the shrunk one: RapidCheck only continues from failing shrinks.
  std::optional<std::pair<ExplorationCase, Divergence>> last_failure;
  const auto property = [&] {
    const ExplorationCase c = *gen_exploration_case(o.max_steps);
    LockstepReach reach;
    const auto d = run_lockstep(c.scenario, impl_options(c), &reach);
    if (!report.counterexample) note_coverage(c, reach, report.coverage);
    if (d) {
      last_failure.emplace(c, *d);
      if (!report.counterexample) report.counterexample.emplace();
    }
    RC_ASSERT(!d.has_value());
  };
  const CampaignRun run = run_campaign("exploration: impl equals model bit for bit", o.seed, o.cases, property,
                                      o.on_case);
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

}  // namespace swarmcheck::conformance::exploration
