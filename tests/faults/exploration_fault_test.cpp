// The mutation check: this file is compiled once per fault of tests/faults/exploration/, linked
// with the variant of the library that carries it, and `conform` with its default case budget
// must catch the fault under the seed it is given (SWARMCHECK_FAULT_SEED), shrink it and write a
// trace that replays: the model reproduces every record, the faulty library parts from it at the
// recorded step (or crashes or hangs there, run in a child process as the campaign runs it).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "conformance/exploration/conform.hpp"
#include "conformance/exploration/trace_io.hpp"
#include "tests/faults/fault_seed.hpp"

using namespace swarmcheck::conformance::exploration;
namespace faults = swarmcheck::testing::faults;

TEST(Mutation, ConformCatchesTheInjectedFaultWithAMinimalReplayableTrace) {
  ConformOptions o;   // the default case budget
  o.seed = faults::seed();
  o.quiet_limit = faults::quiet_limit();
  o.out_dir = (std::filesystem::temp_directory_path() /
               (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid())))
                  .string();
  const ConformReport r = run_conform(o);
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived " << r.cases_run
                                            << " cases with seed " << o.seed;
  const Counterexample& cx = *r.counterexample;
  faults::check_expected(cx.divergence.describe());
  ASSERT_TRUE(std::filesystem::exists(cx.trace_path));
  const ReplayResult on_model = replay_trace(cx.trace_path, Engine::model);
  EXPECT_FALSE(on_model.divergence.has_value()) << on_model.divergence->describe();
  EXPECT_EQ(on_model.records, cx.divergence.step + 1);
  // The minimal case reproduces by itself: same step, same field, same values (or the same end).
  // (In a child, before this process runs the library itself and starts its worker threads.)
  const auto again = run_case_isolated(cx.minimal, o.quiet_limit);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->describe(), cx.divergence.describe());
  if (cx.divergence.abnormal_end.empty()) {   // an impl that crashes is replayed in a child only
    const ReplayResult on_impl = replay_trace(cx.trace_path, Engine::impl);
    ASSERT_TRUE(on_impl.divergence.has_value());
    EXPECT_EQ(on_impl.divergence->step, cx.divergence.step);
  }
  const auto& s = cx.minimal.scenario;
  std::printf("fault %s (seed %llu): caught after %d cases; %s family; shrunk %d times to map %d, %zu robots, "
              "%zu obstacles, %s/%s; trace %lld steps; %s\n",
              kFaultName, static_cast<unsigned long long>(o.seed), r.cases_run,
              std::string(family_name(cx.caught_by)).c_str(), cx.shrinks, s.map_size, s.robots.size(),
              s.obstacles.size(), swarmcheck::json_io::enum_to_string(s.rule).c_str(),
              swarmcheck::json_io::enum_to_string(s.mode).c_str(), static_cast<long long>(cx.divergence.step),
              cx.divergence.describe().c_str());
  std::filesystem::remove_all(o.out_dir);
}
