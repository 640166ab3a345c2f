// Running work in a child process (conformance/common/child_process.hpp): what the parent learns
// of a child that finishes, throws, crashes, exits or hangs, and that a child which keeps
// reporting progress is never taken for a hung one.
#include "conformance/common/child_process.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "spec/util/input_error.hpp"

namespace swarmcheck::conformance {
namespace {

using namespace std::chrono_literals;
using Side = CaseProgress::Side;

TEST(ChildProcess, AFinishedChildHandsBackWhatItsWorkReturned) {
  const ChildEnd end = run_in_child([](CaseProgress& p) {
    p.at(4, Side::model);
    return std::string("agreed\0with a zero byte", 23);
  }, ChildLimits{10s});
  ASSERT_TRUE(end.finished()) << end.describe();
  EXPECT_EQ(end.output, std::string("agreed\0with a zero byte", 23));
  EXPECT_EQ(end.step, 4);
  EXPECT_EQ(end.side, Side::model);
}

TEST(ChildProcess, ACrashIsReportedWithItsSignalAndTheLastStepAndSideReached) {
  const ChildEnd end = run_in_child([](CaseProgress& p) -> std::string {
    p.at(11, Side::model);
    p.at(12, Side::impl);
    std::raise(SIGSEGV);
    return "never";
  }, ChildLimits{10s});
  EXPECT_EQ(end.how, ChildEnd::How::crashed);
  EXPECT_EQ(end.signal, SIGSEGV);
  EXPECT_EQ(end.describe(), "impl crashed with SIGSEGV at step 12");
}

TEST(ChildProcess, AnAbortWithoutProgressIsTheCasesCrash) {
  const ChildEnd end = run_in_child([](CaseProgress&) -> std::string { std::abort(); }, ChildLimits{10s});
  EXPECT_EQ(end.how, ChildEnd::How::crashed);
  EXPECT_EQ(end.describe(), "the case crashed with SIGABRT");
}

TEST(ChildProcess, AnExceptionInTheChildIsReportedWithItsMessage) {
  const ChildEnd end = run_in_child([](CaseProgress& p) -> std::string {
    p.at(3, Side::impl);
    throw std::logic_error("index out of range");
  }, ChildLimits{10s});
  EXPECT_EQ(end.how, ChildEnd::How::threw);
  EXPECT_EQ(end.describe(), "impl threw at step 3: index out of range");
}

TEST(ChildProcess, AChildThatExitsWithoutAnswerIsReportedWithItsStatus) {
  const ChildEnd end = run_in_child([](CaseProgress&) -> std::string { std::_Exit(7); }, ChildLimits{10s});
  EXPECT_EQ(end.how, ChildEnd::How::exited);
  EXPECT_EQ(end.exit_status, 7);
}

TEST(ChildProcess, AChildWithoutProgressForTheLimitIsStoppedAndCountsAsHung) {
  const ChildEnd end = run_in_child([](CaseProgress& p) -> std::string {
    p.at(5, Side::impl);
    for (;;) std::this_thread::sleep_for(1s);
  }, ChildLimits{300ms});
  EXPECT_EQ(end.how, ChildEnd::How::hung);
  EXPECT_EQ(end.describe(), "impl hung at step 5 (no progress for 300 ms)");
}

TEST(ChildProcess, AChildThatKeepsReportingStepsIsNotHungHoweverLongItRuns) {
  // Twice the limit in all, a step every tenth of it.
  const ChildEnd end = run_in_child([](CaseProgress& p) {
    for (int step = 0; step < 20; ++step) {
      p.at(step, Side::impl);
      std::this_thread::sleep_for(100ms);
    }
    return std::string("done");
  }, ChildLimits{1s});
  ASSERT_TRUE(end.finished()) << end.describe();
  EXPECT_EQ(end.output, "done");
}

TEST(ChildProcess, AFirstPassThatCrashesGivesNoReportButTheCasesItSawAgree) {
  const FirstPass first = run_campaign_in_child([](CaseProgress& p) -> std::string {
    p.agreed(41);
    std::raise(SIGSEGV);
    return "never";
  }, ChildLimits{10s});
  EXPECT_FALSE(first.report.has_value());
  EXPECT_EQ(first.cases_agreed, 41);
}

TEST(ChildProcess, AFirstPassInputErrorIsThrownAgainInTheParentWithItsPlace) {
  try {
    (void)run_campaign_in_child([](CaseProgress&) -> std::string {
      throw InputError("out/trace.json", "a folder that can be written");
    }, ChildLimits{10s});
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "out/trace.json");
    EXPECT_STREQ(e.what(), "out/trace.json: a folder that can be written");
  }
}

}  // namespace
}  // namespace swarmcheck::conformance
