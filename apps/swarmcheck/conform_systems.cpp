#include "apps/swarmcheck/conform_systems.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include "conformance/mission/campaign.hpp"
#include "conformance/supervisor/campaign.hpp"

namespace swarmcheck::cli {

using json_io::Json;

namespace {

conformance::CaseCallback progress_of(const SystemCampaign& c, const char* what) {
  if (!c.progress) return {};
  return [what](int done, int asked) {
    if (done % 10 == 0 || done == asked) fmt::print(stderr, "\r{} case {} / {}", what, done, asked);
  };
}

void clear_progress(const SystemCampaign& c) {
  if (c.progress) fmt::print(stderr, "\r{:50}\r", "");
}

// A report object: into the combined report when there is one, else printed.
void emit(const Json& j, Json* json_out) {
  if (json_out)
    *json_out = j;
  else
    fmt::print("{}\n", j.dump());
}

void print_counts(const char* title, const std::map<std::string, int>& counts) {
  for (const auto& [k, n] : counts) fmt::print("  {} {:<28} {:>6}\n", title, k, n);
}

}  // namespace

int conform_automata(const SystemCampaign& c, Json* json_out) {
  namespace cs = conformance::supervisor;
  cs::CampaignOptions o;
  if (c.cases > 0) o.cases = c.cases;
  o.seed = conformance::derive_seed(c.seed, "automata");
  o.out_dir = c.out_dir;
  o.on_case = progress_of(c, "automata");
  o.quiet_limit = c.quiet_limit;
  const cs::CampaignReport r = cs::run_campaign(o);
  clear_progress(c);
  const auto& v = r.coverage;
  const Json coverage{{"cases_by_kind", v.cases_by_kind},
                      {"largest_unary_states", v.largest_unary_states},
                      {"largest_product_states", v.largest_product_states},
                      {"largest_plant_states", v.largest_plant_states},
                      {"largest_supervisor_states", v.largest_supervisor_states},
                      {"empty_supervisors", v.empty_supervisors},
                      {"inclusions_failing", v.inclusions_failing}};
  if (c.json) {
    Json j{{"agree", !r.counterexample}, {"cases_run", r.cases_run}, {"seed", c.seed}, {"campaign_seed", o.seed}};
    if (c.stats) j["coverage"] = coverage;
    if (r.counterexample)
      j["counterexample"] = {{"kind", r.counterexample->kind}, {"difference", r.counterexample->difference},
                             {"files", r.counterexample->files}, {"command", r.counterexample->command},
                             {"shrinks", r.counterexample->shrinks}, {"states", r.counterexample->states}};
    emit(j, json_out);
  } else if (!r.counterexample) {
    fmt::print("conform automata: impl and model agree exactly on {} cases (seed {})\n", r.cases_run, c.seed);
  } else {
    const auto& x = *r.counterexample;
    fmt::print("conform automata: DIFFERENCE after {} cases (seed {}); {} case shrunk {} times to {} states in all\n"
               "  {}\n  files: {}\n  show: {}\n  reproduce: swarmcheck conform --system automata --seed {} --cases {}\n",
               r.cases_run, c.seed, x.kind, x.shrinks, x.states, x.difference, fmt::join(x.files, " "),
               x.command, c.seed, o.cases);
  }
  if (c.stats && !c.json) {
    print_counts("kind", v.cases_by_kind);
    fmt::print("  largest unary input               {:>6} states\n", v.largest_unary_states);
    fmt::print("  largest product built             {:>6} states\n", v.largest_product_states);
    fmt::print("  largest synthesis plant           {:>6} states\n", v.largest_plant_states);
    fmt::print("  largest supervisor                {:>6} states\n", v.largest_supervisor_states);
    fmt::print("  empty supervisors                 {:>6}\n", v.empty_supervisors);
    fmt::print("  failing inclusions (witnesses)    {:>6}\n", v.inclusions_failing);
  }
  return r.counterexample ? 1 : 0;
}

int conform_missions(const SystemCampaign& c, Json* json_out) {
  namespace cm = conformance::mission;
  cm::CampaignOptions o;
  if (c.cases > 0) o.cases = c.cases;
  o.seed = conformance::derive_seed(c.seed, "missions");
  o.out_dir = c.out_dir;
  o.on_case = progress_of(c, "missions");
  o.quiet_limit = c.quiet_limit;
  const cm::CampaignReport r = cm::run_campaign(o);
  clear_progress(c);
  const auto& v = r.coverage;
  const Json coverage{{"cases_by_kind", v.cases_by_kind},   {"run_endings", v.run_endings},
                      {"query_streams", v.query_streams},   {"stream_queries", v.stream_queries},
                      {"repeated_queries", v.repeated_queries}, {"plans_found", v.plans_found},
                      {"plans_absent", v.plans_absent}, {"runs_with_yields", v.runs_with_yields},
                      {"runs_with_steering", v.runs_with_steering}, {"runs_with_bumps", v.runs_with_bumps},
                      {"runs_rerouted_on_sensing", v.runs_rerouted_on_sensing}};
  if (c.json) {
    Json j{{"agree", !r.counterexample}, {"cases_run", r.cases_run}, {"seed", c.seed}, {"campaign_seed", o.seed}};
    if (c.stats) j["coverage"] = coverage;
    if (r.counterexample) {
      const auto& x = *r.counterexample;
      j["counterexample"] = {{"kind", x.kind}, {"difference", x.difference}, {"mission", x.mission_path},
                             {"fsm", x.fsm_path}, {"queries", x.queries_path}, {"command", x.command},
                             {"shrinks", x.shrinks}, {"fsm_states", x.fsm_states}, {"robots", x.robots},
                             {"tasks", x.tasks}};
    }
    emit(j, json_out);
  } else if (!r.counterexample) {
    fmt::print("conform missions: impl and model agree on {} cases (seed {})\n", r.cases_run, c.seed);
  } else {
    const auto& x = *r.counterexample;
    fmt::print("conform missions: DIFFERENCE after {} cases (seed {}); {} case shrunk {} times to {} robots, {} tasks, "
               "{} FSM states\n  {}\n  mission: {}{}\n  show: {}\n  reproduce: swarmcheck conform --system missions "
               "--seed {} --cases {}\n",
               r.cases_run, c.seed, x.kind, x.shrinks, x.robots, x.tasks, x.fsm_states, x.difference, x.mission_path,
               x.queries_path.empty() ? "" : " (queries: " + x.queries_path + ")", x.command, c.seed, o.cases);
  }
  if (c.stats && !c.json) {
    print_counts("kind", v.cases_by_kind);
    print_counts("run ending", v.run_endings);
    fmt::print("  planner query streams             {:>6} ({} queries, {} repeated)\n", v.query_streams,
               v.stream_queries, v.repeated_queries);
    fmt::print("  plans found / no plan             {:>6} / {}\n", v.plans_found, v.plans_absent);
    fmt::print("  runs with a yield / a steering    {:>6} / {}\n", v.runs_with_yields, v.runs_with_steering);
    fmt::print("  runs with a bump / a sensed cell  {:>6} / {}\n", v.runs_with_bumps, v.runs_rerouted_on_sensing);
  }
  return r.counterexample ? 1 : 0;
}

}  // namespace swarmcheck::cli
