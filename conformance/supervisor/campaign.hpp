#pragma once
// The automata campaign: the library (impl/supervisor) against the reference model on generated
// automata, every operation, from one seed. Each case draws one kind:
//   unary       accessible / coaccessible / trim / blocking / nonblocking on up to 300 states
//   product     two automata of up to 40 states over one alphabet
//   big         a product of 2..4 parts with private events: 10^3..10^5 states, so that the growth
//               paths of hash tables and worklists run
//   synthesis   controllability and the supremal controllable nonblocking supervisor
//   big_synth   synthesis for a plant that is itself a big product
//   inclusion   L(a) in L(b) and Lm(a) in Lm(b) both ways, verdicts and shortest witnesses
//   roundtrip   reading what was written gives the automaton back
//   control     a given supervisor: controllable? closed loop nonblocking? shortest witnesses
//   observation with unobservable events: the observer, observability of a specification
//               (verdict and witness words) and the supremal controllable normal supervisor
// Results are compared as the user sees them, never up to renaming: the state count, the state
// names in order (a duplicate name is a difference, never merged), and the bytes `fsm ... -o`
// writes. A failure shrinks (RapidCheck), then loses every state no input reaches and every
// event no transition uses while the difference stays, and is written as .fsm files with the
// `swarmcheck fsm` command that shows it.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "conformance/common/campaign.hpp"
#include "conformance/supervisor/differential.hpp"
#include "spec/supervisor/automaton.hpp"

namespace swarmcheck::conformance::supervisor {

struct CampaignOptions {
  int cases = 400;
  uint64_t seed = 1;
  std::string out_dir = "conform-out";
  CaseCallback on_case;
  // Each case runs in a child process (conformance/common/child_process.hpp); one that runs this
  // long (a case has no steps to show progress by) counts as hung, like a crash: a difference.
  std::chrono::milliseconds quiet_limit{std::chrono::seconds(60)};
};

struct Coverage {
  std::map<std::string, int> cases_by_kind;
  std::size_t largest_unary_states = 0;
  std::size_t largest_product_states = 0;     // states of the biggest product built
  std::size_t largest_plant_states = 0;       // of a synthesis
  std::size_t largest_supervisor_states = 0;
  int empty_supervisors = 0;
  int inclusions_failing = 0;                 // verdicts "no" (witnesses compared)
};

struct Counterexample {
  std::string kind;
  std::string caught_by;   // the kind of the case that first failed (shrinking may change it)
  std::string difference;
  std::vector<swarmcheck::supervisor::Automaton> inputs;   // minimal
  std::vector<std::string> files;                          // the inputs as .fsm files
  std::string command;                                     // shows the difference on the CLI
  int shrinks = 0;
  int shrink_tries = 0;   // shrink candidates tried, within the runner's budget
  std::size_t states = 0;                                  // of the minimal inputs, all together
};

struct CampaignReport {
  int cases_run = 0;
  Coverage coverage;                       // of the cases before the first failure
  std::optional<Counterexample> counterexample;
};

CampaignReport run_campaign(const CampaignOptions& o);

// The difference (or nothing) of one kind of case on given inputs: what the campaign checks (in
// this process: the campaign runs it in a child).
std::optional<std::string> diff_case(const std::string& kind, const std::vector<swarmcheck::supervisor::Automaton>& in,
                                     BuiltSizes* built = nullptr);
// The same in a child process, as the campaign reports it: a crash or a hang included, said to be
// the library's when the model alone gets through the case ("impl crashed with SIGSEGV (...)").
std::optional<std::string> diff_case_isolated(const std::string& kind,
                                              const std::vector<swarmcheck::supervisor::Automaton>& in,
                                              std::chrono::milliseconds quiet_limit);

}  // namespace swarmcheck::conformance::supervisor
