// The conformance campaign: impl/supervisor against model/supervisor on random deterministic
// automata, every operation. A failure shrinks to a minimal automaton (or pair) and writes it as
// .fsm files into $SWARMCHECK_CEX_DIR (default: ./supervisor-counterexamples).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>

#include "conformance/supervisor/differential.hpp"
#include "conformance/supervisor/generators.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "impl/supervisor/operations.hpp"
#include "model/supervisor/operations.hpp"

namespace {

using namespace swarmcheck::conformance::supervisor;
namespace impl = swarmcheck::impl::supervisor;
namespace model = swarmcheck::model::supervisor;

// The campaign's size: 1000 cases per property (a second or two in all) unless the caller sets
// RC_PARAMS (seed=..., reproduce=..., max_success=...). Set before main, so before RapidCheck
// reads its configuration.
const bool kCampaignSize = [] { return ::setenv("RC_PARAMS", "max_success=1000", 0) == 0; }();

std::string cex_dir() {
  const char* d = std::getenv("SWARMCHECK_CEX_DIR");
  return d ? d : "supervisor-counterexamples";
}

// Fails the property with the difference and where the (so far smallest) automata were written.
void fail_with(const std::string& stem, const std::vector<Automaton>& automata,
               const std::string& difference) {
  const auto paths = write_counterexample(cex_dir(), stem, automata);
  std::string where;
  for (const auto& p : paths) where += " " + p;
  RC_FAIL(difference + "\ncounterexample written to:" + where);
}

// Sizes: unary operations on up to 300 states; products of two 40-state automata; synthesis for
// 100-state plants and 30-state specs, made dense and well marked so that most supervisors are
// not empty. The model's string-keyed passes make bigger pairs slow, not more telling.
RC_GTEST_PROP(SupervisorConformance, ImplEqualsModelOnAccessibleCoaccessibleTrimNonblocking, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton a = *gen_automaton(alphabet, {300, 40, 20});
  if (const auto d = diff_unary(a)) fail_with("unary", {a}, *d);
}

RC_GTEST_PROP(SupervisorConformance, ImplEqualsModelOnSynchronousProduct, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton a = *gen_automaton(alphabet, {40, 60, 30});
  const Automaton b = *gen_automaton(alphabet, {40, 60, 30});
  if (const auto d = diff_product(a, b)) fail_with("product", {a, b}, *d);
}

RC_GTEST_PROP(SupervisorConformance, ImplEqualsModelOnControllabilityAndSupervisor, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton plant = *gen_automaton(alphabet, {100, 70, 70});
  const Automaton spec = *gen_automaton(alphabet, {30, 95, 70});
  RC_CLASSIFY(model::supcon(plant, spec).states.empty(), "empty supervisor");
  if (const auto d = diff_synthesis(plant, spec)) fail_with("synthesis", {plant, spec}, *d);
}

RC_GTEST_PROP(SupervisorConformance, WritingThenReadingAnAutomatonGivesItBack, ()) {
  const Alphabet alphabet = *gen_alphabet();
  const Automaton a = *gen_automaton(alphabet, {100, 60, 30});
  RC_ASSERT(impl::read_fsm(impl::write_fsm(a), "roundtrip") == a);
}

// The canary: a deliberately wrong supervisor (forgets uncontrollability: trim of the product)
// must be told apart from the model's, or the harness could not catch anything.
TEST(SupervisorConformance, CanaryWrongSupervisorIsCaught) {
  const bool passed = rc::check("canary: trim(plant || spec) as the supervisor", [] {
    const Alphabet alphabet = *gen_alphabet();
    const Automaton plant = *gen_automaton(alphabet, {12, 70, 30});
    const Automaton spec = *gen_automaton(alphabet, {6, 90, 50});
    const Automaton wrong = model::trim(model::product({plant, spec}, {"plant", "spec"}));
    RC_ASSERT(canonical(wrong) == canonical(model::supcon(plant, spec)));
  });
  EXPECT_FALSE(passed) << "the harness did not catch a supervisor that ignores controllability";
}

}  // namespace
