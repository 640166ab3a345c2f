#pragma once
// The mission campaign: the library's planner and runner against the reference model on
// generated missions, from one seed. Each case draws one kind:
//   run      a mission run, library vs the model's fixed-step loop: the whole result and every
//            event and step record, doubles by bits (differential.hpp, diff_run)
//   plan     the exact planner vs brute force on a small supervisor: found or not, the cost bit
//            for bit (per-robot travel, makespan, total), the plan a marked path of that cost
//   ties     the same on missions laid out on a 3-4-5 lattice, so that many assignments share
//            a makespan and only the total (or nothing) tells them apart
//   swap     two robots split two tasks either way and meet again in one FSM state: one node,
//            two travel vectors, and a continuation that favours the one with the larger makespan
//   allocation  the same on small task-allocation supervisors, where many paths reach one
//            (state, positions) node with different travel, so the dominance test matters
//   stream   one planner answers a stream of queries (other states, positions, committed
//            travel, repeats, and neighbours of earlier queries that differ in one field), each
//            compared whole (events, final state, cost) with a fresh planner's answer and by
//            cost with brute force: caching across different queries
//   sensing  a run in a world with unknown obstacles and a range sensor (generate.hpp,
//            sensing_case): scans, cells learnt, legs re-routed, bumps
// Each case runs in a child process (conformance/common/child_process.hpp): a crash or a hang of
// the library is a difference ("impl crashed with SIGSEGV at step 40"), shrunk like any other.
// A failure shrinks (RapidCheck) and is written as a mission JSON file with its .fsm, which
// `swarmcheck mission plan` / `mission run` load, with the command that shows it (a stream also
// gets its queries as JSON).
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "conformance/common/campaign.hpp"
#include "spec/mission/run.hpp"

namespace swarmcheck::conformance::mission {

struct CampaignOptions {
  int cases = 300;
  uint64_t seed = 1;
  std::string out_dir = "conform-out";
  CaseCallback on_case;
  // A case that shows no progress (a run step, a planner call) for this long counts as hung.
  std::chrono::milliseconds quiet_limit{std::chrono::seconds(60)};
};

struct Coverage {
  std::map<std::string, int> cases_by_kind;
  std::map<std::string, int> run_endings;   // complete, deadlock, time limit, no plan
  int query_streams = 0;
  int stream_queries = 0;
  int repeated_queries = 0;                 // answered from the planner's memory
  int plans_found = 0;
  int plans_absent = 0;                     // no marked state reachable (compared too)
  int runs_with_yields = 0;                 // a robot gave way to another (rule 3)
  int runs_with_steering = 0;               // a robot steered round another (steering.hpp)
  int runs_with_bumps = 0;                  // a robot bumped into an unknown obstacle (sensing.hpp)
  int runs_rerouted_on_sensing = 0;         // a scan or a bump put a new cell on a robot's map
};

struct CampaignCounterexample {
  std::string kind;
  std::string caught_by;    // the kind of the case that first failed (shrinking may change it)
  std::string difference;
  std::string mission_path, fsm_path, queries_path;   // queries_path: streams only
  std::string command;
  int shrinks = 0;
  std::size_t fsm_states = 0, robots = 0, tasks = 0;
  std::optional<swarmcheck::mission::RunOptions> run_options;   // run kinds: the options it ran with
};

struct CampaignReport {
  int cases_run = 0;
  Coverage coverage;
  std::optional<CampaignCounterexample> counterexample;
};

CampaignReport run_campaign(const CampaignOptions& o);

// A run of the mission (impl against model, as a run case of the campaign) in a child process:
// its difference (a crash or a hang included: "impl crashed with SIGSEGV at step 40"), or nothing.
std::optional<std::string> diff_run_isolated(const swarmcheck::mission::Mission& m,
                                             const swarmcheck::mission::RunOptions& o,
                                             std::chrono::milliseconds quiet_limit);

}  // namespace swarmcheck::conformance::mission
