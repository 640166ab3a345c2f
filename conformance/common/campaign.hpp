#pragma once
// One way to run a seeded RapidCheck campaign for every subsystem's harness: the same seed and
// case budget give the same cases, the same shrinking and the same counterexample, whatever
// RC_PARAMS or RapidCheck's global seed say (TigerBeetle's rule: one seed drives everything).
//
//   CampaignRun r = run_campaign("automata", seed, cases, property, on_case);
//
// `property` is a RapidCheck property (it uses *gen and RC_ASSERT / RC_FAIL). The runner counts
// the cases that finished before the first failure and the shrink steps RapidCheck accepted; the
// property itself keeps whatever it needs of the last failing (so the smallest) case.
//
// The subsystems' properties run each case in a child process (child_process.hpp), so that a
// crash or a hang is a failing case like any other; a case that hung cost the whole time limit,
// so the property reports it (CaseBudget::hung) and shrinking stops after a few of them.
#include <cstdint>
#include <functional>
#include <string>

namespace swarmcheck::conformance {

struct CampaignRun {
  int cases_run = 0;       // cases generated up to the first failure, it included (or all of them)
  bool failed = false;
  int shrinks = 0;         // accepted shrink steps after the failure
  int shrink_tries = 0;    // shrink candidates tried (accepted or not)
  int hung_tries = 0;      // shrink candidates that hung (each stopped at the time limit)
};

// Called after each case with (cases done, cases asked); may print progress.
using CaseCallback = std::function<void(int, int)>;

// Shrinking stops after `max_shrink_tries` candidates (a big automaton has thousands of
// candidates, each costing a model run of seconds): the counterexample is then the smallest
// failing case found within the budget, and the subsystem's own reduction takes it further.
inline constexpr int kDefaultMaxShrinkTries = 400;
// Shrinking also stops after this many candidates that hung: each took the whole time limit.
inline constexpr int kDefaultMaxHungTries = 6;

struct ShrinkBudget {
  int max_tries = kDefaultMaxShrinkTries;
  int max_hung_tries = kDefaultMaxHungTries;
};

// Handed to the property: it reports a case that hung (counted against max_hung_tries).
class CaseBudget {
 public:
  explicit CaseBudget(CampaignRun& run) : run_(&run) {}
  void hung() {
    if (run_->failed) ++run_->hung_tries;
  }

 private:
  CampaignRun* run_;
};

CampaignRun run_campaign(const std::string& name, uint64_t seed, int cases, const std::function<void()>& property,
                         const CaseCallback& on_case = {}, int max_shrink_tries = kDefaultMaxShrinkTries);
CampaignRun run_campaign(const std::string& name, uint64_t seed, int cases,
                         const std::function<void(CaseBudget&)>& property, const CaseCallback& on_case,
                         const ShrinkBudget& budget);

// Derives the seed of a sub-campaign from a campaign seed and a name (so that one --seed drives
// the campaigns of every subsystem without them drawing the same numbers).
uint64_t derive_seed(uint64_t seed, const std::string& name);

}  // namespace swarmcheck::conformance
