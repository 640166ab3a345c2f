// The public automata API (swarmcheck/supervisor.hpp) as a user calls it: the check report,
// default part names in product errors, files written whole, and values equal to the model's.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "model/supervisor/operations.hpp"
#include "swarmcheck/supervisor.hpp"

namespace {

namespace sv = swarmcheck::supervisor;
namespace fs = std::filesystem;

// s -a-> m (marked), s -b-> d (dead end), u -a-> s (unreachable, coaccessible).
const char* kBlocking = "4\ns 0 2\na m\nb d\nm 1 0\nd 0 0\nu 0 1\na s\n";

TEST(SupervisorApi, CheckReportsUnreachableAndBlockingStatesInOrder) {
  const sv::Automaton a = sv::read_fsm(kBlocking, "t");
  const sv::CheckReport r = sv::check(a);
  EXPECT_EQ(r.unreachable_states, (std::vector<sv::State>{"u"}));
  EXPECT_EQ(r.blocking_states, (std::vector<sv::State>{"d"}));
  EXPECT_FALSE(r.coaccessible);
  EXPECT_FALSE(r.accessible());
  EXPECT_FALSE(r.nonblocking());
  EXPECT_FALSE(sv::is_nonblocking(a));
  EXPECT_TRUE(sv::check(sv::trim(a)).nonblocking());
}

TEST(SupervisorApi, TrimAndAccessiblePartEqualTheModels) {
  const sv::Automaton a = sv::read_fsm(kBlocking, "t");
  EXPECT_EQ(sv::trim(a), swarmcheck::model::supervisor::trim(a));
  EXPECT_EQ(sv::accessible_part(a), swarmcheck::model::supervisor::accessible_part(a));
}

TEST(SupervisorApi, ProductNamesThePartsByPositionWhenNotNamed) {
  const sv::Automaton a = sv::read_fsm("1\nx 1 1\ne x c o\n", "a.fsm");
  const sv::Automaton b = sv::read_fsm("1\ny 1 1\ne y uc o\n", "b.fsm");
  try {
    sv::product({a, b});
    FAIL() << "no error";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_STREQ(e.what(), "part 2: event 'e' is uncontrollable and observable here but "
                           "controllable and observable in part 1");
  }
  EXPECT_THROW(sv::product({}), swarmcheck::InputError);
}

TEST(SupervisorApi, WriteFsmFileIsWholeOrNothing) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck_api_" + std::to_string(::getpid()));
  fs::create_directories(d);
  const sv::Automaton a = sv::read_fsm(kBlocking, "t");
  sv::write_fsm_file((d / "a.fsm").string(), a);
  EXPECT_EQ(sv::read_fsm_file((d / "a.fsm").string()), a);
  EXPECT_THROW(sv::write_fsm_file((d / "no" / "b.fsm").string(), a), swarmcheck::InputError);
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
  fs::remove_all(d);
}

}  // namespace
