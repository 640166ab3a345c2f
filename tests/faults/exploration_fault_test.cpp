// The mutation check: this file is compiled once per fault of tests/faults/exploration/, linked
// with the variant of the library that carries it, and `conform` with its default case budget
// must catch the fault, shrink it and write a trace that replays: the model reproduces every
// record, the faulty library parts from it at the recorded step.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "conformance/exploration/conform.hpp"
#include "conformance/exploration/trace_io.hpp"

using namespace swarmcheck::conformance::exploration;

// The fault this executable carries: one generated line per fault (tests/faults/CMakeLists.txt),
// so this file is compiled once per subsystem and linked with every variant.
extern const char* const kFaultName;

TEST(Mutation, ConformCatchesTheInjectedFaultWithAMinimalReplayableTrace) {
  ConformOptions o;   // the default case budget and seed
  o.out_dir = (std::filesystem::temp_directory_path() /
               (std::string("swarmcheck-fault-") + kFaultName + "-" + std::to_string(::getpid())))
                  .string();
  const ConformReport r = run_conform(o);
  ASSERT_TRUE(r.counterexample.has_value()) << "fault " << kFaultName << " survived "
                                            << r.cases_run << " cases";
  const Counterexample& cx = *r.counterexample;
  ASSERT_TRUE(std::filesystem::exists(cx.trace_path));
  const ReplayResult on_model = replay_trace(cx.trace_path, Engine::model);
  EXPECT_FALSE(on_model.divergence.has_value()) << on_model.divergence->describe();
  EXPECT_EQ(on_model.records, cx.divergence.step + 1);
  const ReplayResult on_impl = replay_trace(cx.trace_path, Engine::impl);
  ASSERT_TRUE(on_impl.divergence.has_value());
  EXPECT_EQ(on_impl.divergence->step, cx.divergence.step);
  // The minimal case reproduces by itself: same step, same field, same values.
  const auto again = run_lockstep(cx.minimal.scenario, impl_options(cx.minimal));
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->describe(), cx.divergence.describe());
  const auto& s = cx.minimal.scenario;
  std::printf("fault %s: caught after %d cases; shrunk %d times to map %d, %zu robots, %zu obstacles, "
              "%s/%s; trace %lld steps; %s\n",
              kFaultName, r.cases_run, cx.shrinks, s.map_size, s.robots.size(), s.obstacles.size(),
              swarmcheck::json_io::enum_to_string(s.rule).c_str(), swarmcheck::json_io::enum_to_string(s.mode).c_str(),
              static_cast<long long>(cx.divergence.step), cx.divergence.describe().c_str());
  std::filesystem::remove_all(o.out_dir);
}
