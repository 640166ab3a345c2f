// --memory-limit and --time-limit on every `fsm` verb whose work can grow exponentially or
// quadratically with its input (issue 38): products (product, synth, controllable), observers
// (project, normal synthesis), the pairs of states an observability check or a comparison
// explores. Past a limit the verb stops cleanly: exit 2, one line saying how far it got, the
// output as it was. Before, `fsm observable` had no budget at all: a 1 000-state chain on one
// unobservable controllable event (25 KB) took 30 CPU s and over 2 GiB.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/util/fsm_gen.hpp"
#include "tests/util/shell.hpp"

namespace fs = std::filesystem;
using swarmcheck::testing::run_binary;
using swarmcheck::testing::ShellResult;
namespace gen = swarmcheck::testing::fsm_gen;

namespace {

const std::string kBin = SWARMCHECK_BIN;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-fsm-budgets-" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Exit 2, one line "swarmcheck: error: " + `files` + ": " ..., containing each of `parts`.
void expect_stopped(const ShellResult& r, const std::string& files, const std::vector<std::string>& parts) {
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out.rfind("swarmcheck: error: " + files + ": ", 0), 0U) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  for (const auto& p : parts) EXPECT_NE(r.out.find(p), std::string::npos) << "expected \"" << p << "\" in: " << r.out;
}

// The chain of the issue: every pair of its states looks alike to a supervisor (one unobservable
// event), so the observability check compares n^2 pairs.
TEST(FsmBudgets, ObservableOnTheIssuesChainStopsAtTheMemoryOrTimeLimitWithThePairsCompared) {
  const fs::path d = scratch("observable");
  const std::string chain = gen::write(d / "chain.fsm", gen::chain(1000, "a", "c\tuo"));
  const std::string files = chain + " || " + chain;
  expect_stopped(run_binary(kBin, "fsm observable --plant " + chain + " --spec " + chain + " --memory-limit 64M"), files,
                 {"the observability check stopped after comparing ", "pairs of words' states", "over the limit of 64.0 MiB",
                  "raise it with --memory-limit"});
  // A 3 000-state chain's 9 x 10^6 pairs take about 10 s and 700 MB here (the 1 000-state one about
  // 1 s, too close to a limit): a 2 s limit stops it well before the verdict.
  const std::string big = gen::write(d / "big.fsm", gen::chain(3000, "a", "c\tuo"));
  expect_stopped(run_binary(kBin, "fsm observable --plant " + big + " --spec " + big + " --time-limit 2 --memory-limit 0"),
                 big + " || " + big, {"the observability check stopped after comparing ", "the --time-limit of 2 s is over"});
  // A chain of 60 fits both limits and gets its verdict.
  const std::string small = gen::write(d / "small.fsm", gen::chain(60, "a", "c\tuo"));
  const auto r = run_binary(kBin, "fsm observable --plant " + small + " --spec " + small + " --memory-limit 64M --time-limit 60 --json");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\"observable\": true"), std::string::npos) << r.out;
}

TEST(FsmBudgets, ProductSynthAndControllableStopAtTheTimeLimitWithTheStatesExplored) {
  const fs::path d = scratch("product");
  const std::string x = gen::write(d / "x.fsm", gen::counter(3000, "x"));
  const std::string y = gen::write(d / "y.fsm", gen::counter(3001, "y"));
  const std::string out = gen::write(d / "out.fsm", "old");
  expect_stopped(run_binary(kBin, "fsm product " + x + " " + y + " -o " + out + " --time-limit 0.1"), x + " || " + y,
                 {"the product stopped after exploring ", "the --time-limit of 0.1 s is over (raise it with --time-limit"});
  expect_stopped(run_binary(kBin, "fsm synth --plant " + x + " " + y + " --spec " + x + " -o " + out + " --time-limit 0.1"), x + " || " + y,
                 {"the product stopped after exploring ", "--time-limit"});
  expect_stopped(run_binary(kBin, "fsm controllable --plant " + x + " " + y + " --sup " + x + " --time-limit 0.1"), x + " || " + y,
                 {"the product stopped after exploring ", "--time-limit"});
  expect_stopped(run_binary(kBin, "fsm controllable --plant " + x + " " + y + " --sup " + x + " --memory-limit 32M"), x + " || " + y,
                 {"the product stopped after exploring ", "over the limit of 32.0 MiB"});
  EXPECT_EQ(read(out), "old");
}

TEST(FsmBudgets, ProjectAndNormalSynthesisStopAtTheTimeLimitWithTheObserverClassesFound) {
  const fs::path d = scratch("observer");
  const std::string plant = gen::write(d / "guess.fsm", gen::exponential_observer(26));
  const std::string spec = gen::write(d / "all.fsm", "1\n\ns 1 3\na s c o\nb s c o\nu s uc uo\n");
  const std::string out = gen::write(d / "out.fsm", "old");
  expect_stopped(run_binary(kBin, "fsm project " + plant + " -o " + out + " --time-limit 0.2 --memory-limit 0"), plant,
                 {"the observer stopped after ", "classes (", "the --time-limit of 0.2 s is over"});
  expect_stopped(run_binary(kBin, "fsm synth --plant " + plant + " --spec " + spec + " -o " + out + " --time-limit 0.2 --memory-limit 0"),
                 plant + " || " + spec, {"the observer stopped after ", "the --time-limit of 0.2 s is over"});
  EXPECT_EQ(read(out), "old");
}

TEST(FsmBudgets, CompareStopsAtTheTimeOrMemoryLimitWithThePairsExplored) {
  const fs::path d = scratch("compare");
  // Two counters of coprime lengths on one event: the comparison meets every pair (9 million).
  const std::string a = gen::write(d / "a.fsm", gen::counter(2999, "x"));
  const std::string b = gen::write(d / "b.fsm", gen::counter(3001, "x"));
  expect_stopped(run_binary(kBin, "fsm compare " + a + " " + b + " --time-limit 0.1"), a + ", " + b,
                 {"the comparison stopped after exploring ", "pairs of states", "the --time-limit of 0.1 s is over"});
  expect_stopped(run_binary(kBin, "fsm compare " + a + " " + b + " --memory-limit 64M"), a + ", " + b,
                 {"the comparison stopped after exploring ", "over the limit of 64.0 MiB"});
}

TEST(FsmBudgets, ATimeLimitThatIsNotADurationIsAUsageError) {
  const fs::path d = scratch("usage");
  const std::string a = gen::write(d / "a.fsm", gen::counter(3, "x"));
  for (const std::string bad : {"-1", "ten", "5d", "1e99"}) {
    const auto r = run_binary(kBin, "fsm project " + a + " --time-limit " + bad);
    EXPECT_EQ(r.status, 2) << bad << ": " << r.out;
    EXPECT_NE(r.out.find("expected a duration such as 30, 30s, 5m or 2h"), std::string::npos) << r.out;
  }
  EXPECT_EQ(run_binary(kBin, "fsm project " + a + " --time-limit 2m").status, 0);
}

}  // namespace
