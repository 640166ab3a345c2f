#include "conformance/common/campaign.hpp"

#include <rapidcheck.h>
#include <rapidcheck/detail/Configuration.h>

#include <iostream>
#include <sstream>

namespace swarmcheck::conformance {
namespace {

// RapidCheck reports through a listener; this one only counts (the callers print their own).
class CountingListener : public rc::detail::TestListener {
 public:
  CountingListener(int cases, const CaseCallback& on_case, CampaignRun& run)
      : cases_(cases), on_case_(on_case), run_(run) {}
  void onTestCaseFinished(const rc::detail::CaseDescription& c) override {
    if (run_.failed) return;
    ++run_.cases_run;   // the failing case counts: "caught after N cases"
    run_.failed = c.result.type == rc::detail::CaseResult::Type::Failure;
    if (on_case_) on_case_(run_.cases_run, cases_);
  }
  void onShrinkTried(const rc::detail::CaseDescription&, bool accepted) override {
    ++run_.shrink_tries;
    if (accepted) ++run_.shrinks;
  }
  void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}

 private:
  int cases_;
  const CaseCallback& on_case_;
  CampaignRun& run_;
};

// RapidCheck announces its global random seed on stderr when it first loads its configuration.
// A campaign passes its own seed, so that banner would only mislead: load it once, muted.
void silence_rapidcheck_banner() {
  std::ostringstream sink;
  std::streambuf* saved = std::cerr.rdbuf(sink.rdbuf());
  (void)rc::detail::configuration();
  std::cerr.rdbuf(saved);
}

}  // namespace

CampaignRun run_campaign(const std::string& name, uint64_t seed, int cases, const std::function<void()>& property,
                         const CaseCallback& on_case, int max_shrink_tries) {
  return run_campaign(name, seed, cases, [&](CaseBudget&) { property(); }, on_case,
                      ShrinkBudget{max_shrink_tries, kDefaultMaxHungTries});
}

CampaignRun run_campaign(const std::string& name, uint64_t seed, int cases,
                         const std::function<void(CaseBudget&)>& property, const CaseCallback& on_case,
                         const ShrinkBudget& budget) {
  silence_rapidcheck_banner();
  CampaignRun run;
  rc::detail::TestParams params;
  params.seed = seed;
  params.maxSuccess = cases;
  params.maxSize = 100;
  params.disableShrinking = false;
  CountingListener listener(cases, on_case, run);
  rc::detail::TestMetadata metadata;
  metadata.id = name;
  metadata.description = name;
  // The shrink budget: past it, every further candidate is reported as passing, so RapidCheck
  // stops at the smallest failing case found so far. Counted in tries, not seconds, so the same
  // seed still gives the same counterexample on any machine.
  CaseBudget case_budget(run);
  const auto bounded = [&] {
    if (run.failed && (run.shrink_tries >= budget.max_tries || run.hung_tries >= budget.max_hung_tries)) return;
    property(case_budget);
  };
  const auto result = rc::detail::checkTestable(std::function<void()>(bounded), metadata, params, listener);
  run.failed = run.failed || result.template is<rc::detail::FailureResult>();
  return run;
}

uint64_t derive_seed(uint64_t seed, const std::string& name) {
  uint64_t h = seed ^ 0x9e3779b97f4a7c15ULL;
  for (const char c : name) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  h ^= h >> 31;
  h *= 0xbf58476d1ce4e5b9ULL;
  return h ^ (h >> 29);
}

}  // namespace swarmcheck::conformance
