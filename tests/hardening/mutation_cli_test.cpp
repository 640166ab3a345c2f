// Hardening by mutation, from the outside: a few hundred bad inputs made from the shipped files
// (a fixed seed, so every run makes the same ones), each run through the binary. The contract of
// README "The command line": bad input of any kind gets exit status 2 and one short message
// naming the file and where (line:col or JSON path); never status 3 ("internal error"), a signal
// or a hang. An odd input that is still valid may give 0 or 1. No input file is changed, and a
// failed command leaves a pre-existing output file with its exact bytes and no temp file beside
// it.
//
// A failure names the mutation class and what was changed, saves the mutated input under
// $TMPDIR/swarmcheck-mutation-failures/ and prints the command to run it again.
// SWARMCHECK_MUTATION_SEED and SWARMCHECK_MUTATIONS (mutants per shipped file) change the set;
// SWARMCHECK_MUTATION_VERBOSE=1 prints every run.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "tests/hardening/mutation/harness.hpp"
#include "tests/hardening/mutation/mutants.hpp"
#include "tests/hardening/mutation/process.hpp"
#include "tests/hardening/mutation/text.hpp"

namespace fs = std::filesystem;
using namespace swarmcheck::testing::mutation;

namespace {

std::string test_name() { return ::testing::UnitTest::GetInstance()->current_test_info()->name(); }

}  // namespace

TEST(MutationCli, AMutatedScenarioGivesStatus0Or1Or2WithOneMessageNamingItAndLeavesTheTraceOutputWhole) {
  MutationHarness h(test_name());
  const JsonKind scenario{"scenario", false,
                          [](std::size_t, const std::string& path) { return path == "map_size" || path == "robots"; }};
  const std::vector<Command> run{{"run --steps 50 --trace OUT",
                                  [](const std::string& in, const std::string& out) {
                                    return std::vector<std::string>{"run", in, "--steps", "50", "--trace", out};
                                  },
                                  true}};
  std::uint64_t salt = 0;
  for (const auto& [file, n] : std::vector<std::pair<std::string, std::size_t>>{
           {"scenarios/default.json", count_for(120)}, {"scenarios/examples/warehouse.json", count_for(90)}}) {
    const std::string text = read_bytes(kSource + "/" + file);
    h.check(fs::path(file).filename().string(), text, json_mutants(text, scenario, n, seed_for(0x5eed0001 + salt++)),
            run);
  }
  h.report();
}

TEST(MutationCli, AMutatedMissionGivesStatus0Or1Or2WithOneMessageNamingItAndLeavesTheTraceOutputWhole) {
  MutationHarness h(test_name());
  h.fixture(kSource + "/scenarios/thesis/control2.fsm");
  // Every key of a mission is needed except the free text "about" and the meanings of events the
  // FSM does not have (checked, then ignored).
  std::set<std::string> fsm_events;
  {
    std::istringstream in(read_bytes(kSource + "/scenarios/thesis/control2.fsm"));
    for (std::string line; std::getline(in, line);) {
      std::istringstream f(line);
      std::vector<std::string> fields{std::istream_iterator<std::string>(f), {}};
      if (fields.size() == 4) fsm_events.insert(fields[0]);
    }
  }
  ASSERT_TRUE(fsm_events.count("a5e"));
  const JsonKind mission{"mission", false, [fsm_events](std::size_t, const std::string& path) {
                           if (path == "about") return false;
                           if (path.rfind("events.", 0) == 0 && path.find('.', 7) == std::string::npos)
                             return fsm_events.count(path.substr(7)) > 0;
                           return true;
                         }};
  const std::vector<Command> commands{{"mission plan",
                                       [](const std::string& in, const std::string&) {
                                         return std::vector<std::string>{"mission", "plan", in};
                                       }},
                                      {"mission run --trace OUT",
                                       [](const std::string& in, const std::string& out) {
                                         return std::vector<std::string>{"mission",   "run",     in,    "--body",
                                                                         "kinematic", "--speed", "100", "--max-time",
                                                                         "100",       "--trace", out};
                                       },
                                       true}};
  const std::string text = read_bytes(kSource + "/scenarios/thesis/thesis-mission.json");
  h.check("thesis-mission.json", text, json_mutants(text, mission, count_for(150), seed_for(0x5eed0002)), commands);
  h.report();
}

TEST(MutationCli, AMutatedFsmFileGivesStatus0Or1Or2WithOneMessageNamingItAndLeavesTheExportOutputWhole) {
  MutationHarness h(test_name());
  const std::vector<Command> commands{{"fsm check",
                                       [](const std::string& in, const std::string&) {
                                         return std::vector<std::string>{"fsm", "check", in};
                                       }},
                                      {"fsm check --json",
                                       [](const std::string& in, const std::string&) {
                                         return std::vector<std::string>{"fsm", "check", in, "--json"};
                                       }},
                                      {"fsm export --to json -o OUT",
                                       [](const std::string& in, const std::string& out) {
                                         return std::vector<std::string>{"fsm",  "export", in, "--to",
                                                                         "json", "-o",     out};
                                       },
                                       true}};
  std::uint64_t salt = 0;
  for (const std::string file : {"control2.fsm", "supervisor.fsm", "supervisor_any_robot.fsm"}) {
    const std::string text = read_bytes(kSource + "/scenarios/thesis/" + file);
    h.check(file, text, fsm_mutants(text, count_for(50), seed_for(0x5eed0003 + salt++)), commands);
  }
  h.report();
}

TEST(MutationCli, AMutatedTraceGivesStatus0Or1Or2WithOneMessageNamingIt) {
  MutationHarness h(test_name());
  const fs::path made = h.dir() / "made.jsonl";
  const Outcome o = run_swarmcheck({"run", "--steps", "30", "--trace", made.string()}, std::chrono::seconds(20));   // 30 steps: not completed (status 1)
  ASSERT_EQ(o.status, 1) << o.err;
  const std::string text = read_bytes(made);
  fs::remove(made);
  // A record must have every field; so must the header, except inside its scenario, where a
  // missing key takes the same default as in a scenario file.
  const JsonKind trace{"trace", true, [](std::size_t root, const std::string& path) {
                         if (root == 0 && path.rfind("scenario.", 0) == 0)
                           return path == "scenario.map_size" || path == "scenario.robots";
                         return true;
                       }};
  const std::vector<Command> replay{{"replay", [](const std::string& in, const std::string&) {
                                       return std::vector<std::string>{"replay", in};
                                     }}};
  h.check("t.jsonl", text, json_mutants(text, trace, count_for(120), seed_for(0x5eed0004)), replay);
  h.report();
}

TEST(MutationCli, AMutatedMissionTraceGivesStatus0Or2WithOneMessageNamingItAndLeavesTheViewOutputWhole) {
  MutationHarness h(test_name());
  const std::string mission = kSource + "/scenarios/thesis/thesis-mission.json";
  const fs::path made = h.dir() / "made.jsonl";
  const Outcome o = run_swarmcheck({"mission", "run", mission, "--body", "kinematic", "--max-time", "3", "--trace", made.string()},
                                   std::chrono::seconds(20));   // 3 s of the mission: not completed (status 1)
  ASSERT_EQ(o.status, 1) << o.err;
  const std::string text = read_bytes(made);
  fs::remove(made);
  // The header needs its type, initial state and robots (the mission comes from --mission); every
  // other record every field but a step's "yielded" (traces from before the yield rule lack it).
  const JsonKind trace{"mission trace", true, [](std::size_t root, const std::string& path) {
                         if (root == 0) return path == "type" || path == "initial_state" || path == "robots";
                         return path != "yielded";
                       }};
  const std::vector<Command> view{{"view --mission M -o OUT",
                                   [mission](const std::string& in, const std::string& out) {
                                     return std::vector<std::string>{"view", in, "--mission", mission, "-o", out};
                                   },
                                   true}};
  h.check("m.jsonl", text, json_mutants(text, trace, count_for(120), seed_for(0x5eed0005)), view);
  h.report();
}

// Not mutations but the same contract: files that are not regular text files.
TEST(MutationCli, AnEmptyMissingDirectoryDeviceOrFifoInputIsStatus2WithinSecondsNotAHangOrACrash) {
  MutationHarness h(test_name());
  const fs::path empty = h.dir() / "empty.json";
  write_bytes(empty, "");
  const fs::path folder = h.dir() / "folder.json";
  fs::create_directories(folder);
  const fs::path fifo = h.dir() / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::vector<std::string> inputs{
      empty.string(), (h.dir() / "missing.json").string(), folder.string(), "/dev/null", "/dev/zero", fifo.string()};
  std::vector<std::string> broken;
  for (const std::vector<std::string>& verb : std::vector<std::vector<std::string>>{
           {"run", "--steps", "5"}, {"replay"}, {"mission", "plan"}, {"fsm", "check"}, {"fsm", "check", "--json"}}) {
    for (const std::string& in : inputs) {
      std::vector<std::string> args = verb;
      args.insert(args.begin() + (verb[0] == "run" ? 1 : static_cast<long>(verb.size())), in);
      // Each is refused at once: a short limit on time and memory keeps a failure cheap.
      const Outcome o = run_swarmcheck(args, std::chrono::seconds(2), 512);
      const std::string name = fs::path(in).filename().string();
      const std::string first = o.err.substr(0, o.err.find('\n'));
      std::string what;
      if (o.timed_out)
        what = "no answer within 2 s";
      else if (o.signal)
        what = "signal " + std::to_string(o.signal);
      else if (o.status != 2)
        what = "status " + std::to_string(o.status);
      else if (first.find(name) == std::string::npos)
        what = "the first line of stderr does not name " + name;
      else if (std::count(o.err.begin(), o.err.end(), '\n') + std::count(o.out.begin(), o.out.end(), '\n') > 3)
        what = "more than 3 lines";
      if (!what.empty()) broken.push_back(joined(args) + ": " + what + "; stderr: " + shown(o.err, 200));
    }
  }
  EXPECT_TRUE(fs::exists(fifo) && fs::is_empty(folder));
  std::string all;
  for (const auto& b : broken) all += "  " + b + "\n";
  EXPECT_TRUE(broken.empty()) << broken.size() << " inputs broke the contract:\n" << all;
}
