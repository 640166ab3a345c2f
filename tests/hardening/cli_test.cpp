// Hardening, from the outside: numbers no double holds, seeds that do not fit, outputs that are
// also inputs. Each is exit status 2 with one message, and no file is changed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "tests/util/shell.hpp"

using swarmcheck::testing::run_binary;
namespace fs = std::filesystem;

namespace {

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-hardening-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST(Hardening, ANumberNoDoubleHoldsIsStatus2AtItsLineAndColumn) {
  const fs::path d = scratch();
  const std::string scenario = write(d / "big.json", "{\"map_size\": 4,\n \"robots\": [[0.5, 1e400]]}");
  const auto r = run_binary(kBin, "run " + scenario);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "swarmcheck: error: " + scenario + ":2:19: a number outside the range of a double (1e400)\n");
}

TEST(Hardening, ASeedOutsideZeroToTwoToThe64IsRefusedNotWrapped) {
  for (const std::string& seed : std::vector<std::string>{"-1", "99999999999999999999", "1.5", "0x10"}) {
    const auto r = run_binary(kBin, "run --steps 1 --seed " + seed);
    EXPECT_EQ(r.status, 2) << seed << ": " << r.out;
    EXPECT_NE(r.out.find("--seed: expected an integer in [0, 18446744073709551615], got " + seed), std::string::npos) << r.out;
  }
  EXPECT_EQ(run_binary(kBin, "run --steps 1 --seed 18446744073709551615").status, 1);   // accepted; 1 step does not complete
  EXPECT_EQ(run_binary(kBin, "conform --system exploration --cases 1 --seed -1").status, 2);
}

TEST(Hardening, AnOutputThatIsAlsoAnInputIsRefusedAndTheInputKept) {
  const fs::path d = scratch();
  const std::string scenario = (d / "s.json").string();
  fs::copy_file(kSource + "/scenarios/default.json", scenario, fs::copy_options::overwrite_existing);
  const std::string before = read(scenario);
  const std::string link = (d / "link.json").string();
  fs::remove(link);
  fs::create_symlink(scenario, link);
  const std::string fsm = (d / "c.fsm").string();
  fs::copy_file(kSource + "/scenarios/thesis/control2.fsm", fsm, fs::copy_options::overwrite_existing);
  const std::string fsm_before = read(fsm);
  for (const std::string& args : std::vector<std::string>{"run " + scenario + " --steps 2 --trace " + scenario,
                                 "run " + scenario + " --steps 2 --svg " + link,
                                 "edit " + scenario + " -o " + scenario,
                                 "fsm export " + fsm + " --to fsm -o " + fsm,
                                 "view " + fsm + " -o " + fsm}) {
    const auto r = run_binary(kBin, args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find("is also an input of this command"), std::string::npos) << r.out;
  }
  EXPECT_EQ(read(scenario), before);
  EXPECT_EQ(read(fsm), fsm_before);
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(run_binary(kBin, "run " + scenario + " --steps 2 --trace " + (d / "t.jsonl").string()).status, 1);
}

TEST(Hardening, ATraceRecordWithAFieldLeftOutIsRejectedNotReplayedAsAgreeing) {
  const fs::path d = scratch();
  const std::string trace = (d / "t.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "run --steps 3 --trace " + trace).status, 1);
  const std::string whole = read(trace);
  ASSERT_EQ(run_binary(kBin, "replay " + trace).status, 0);
  // The third line is the record of step 1: drop its "visited" member.
  std::size_t line3 = whole.find('\n', whole.find('\n') + 1) + 1;
  const std::size_t key = whole.find("\"visited\":", line3);
  ASSERT_NE(key, std::string::npos);
  const std::size_t value_end = whole.find_first_of(",}", key + 10);
  std::string cut = whole;
  cut.erase(key, value_end + 1 - key);
  const std::string broken = write(d / "broken.jsonl", cut);
  const auto r = run_binary(kBin, "replay " + broken);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out, "swarmcheck: error: " + broken + ":3: expected a step record: visited: missing (a record must have every field)\n");
  const std::string bare = write(d / "bare.jsonl", whole.substr(0, line3) + "{\"step\":0}\n");
  const auto b = run_binary(kBin, "replay " + bare);
  EXPECT_EQ(b.status, 2) << b.out;
}
