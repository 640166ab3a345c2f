// Hardening, from the outside (issue 16): each adversarial case of the issue pinned once. Bad
// input and refused work are status 2 with one line naming the file or the flag; signals are
// 130 / 143; no existing file is changed and no temporary file is left behind.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/util/shell.hpp"

using swarmcheck::testing::run_binary;
namespace fs = std::filesystem;

namespace {

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-limits-" + std::to_string(::getpid())) / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// The names in a folder that look like AtomicFile's temporaries (".NAME.tmp-PID-N").
std::vector<std::string> temp_files(const fs::path& d) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(d))
    if (e.path().filename().string().find(".tmp-") != std::string::npos) out.push_back(e.path().string());
  return out;
}

// One line, starting "swarmcheck: error: ", and containing `part`.
void expect_one_error_line(const swarmcheck::testing::ShellResult& r, const std::string& part) {
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out.rfind("swarmcheck: error: ", 0), 0U) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find(part), std::string::npos) << "expected \"" << part << "\" in: " << r.out;
}

std::string mission_with_task_at(const fs::path& d, const std::string& x) {
  auto m = nlohmann::ordered_json::parse(read(kSource + "/scenarios/thesis/thesis-mission.json"));
  m["fsm"] = kSource + "/scenarios/thesis/" + m["fsm"].get<std::string>();
  std::string text = m.dump(1);
  const std::string key = "\"at\": [";
  const std::size_t at = text.find(key);
  const std::size_t comma = text.find(',', at);
  text.replace(at + key.size(), comma - at - key.size(), x);
  return write(d / "m.json", text);
}

}  // namespace

TEST(Limits, JsonNestedDeeperThan512IsStatus2AtTheFirstBracketTooDeep) {
  const fs::path d = scratch("deep");
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string scenario = write(d / "s.json", "{\"robots\": " + deep + ", \"map_size\": 4}");
  expect_one_error_line(run_binary(kBin, "run " + scenario), scenario + ":1:523: nested deeper than 512");
  const std::string mission = write(d / "m.json", deep);
  expect_one_error_line(run_binary(kBin, "mission plan " + mission), mission + ":1:513: nested deeper than 512");
  const std::string trace = write(d / "t.jsonl", deep + "\n");
  expect_one_error_line(run_binary(kBin, "replay " + trace), trace + ":1:513: nested deeper than 512");
}

TEST(Limits, AKeyTwiceInOneObjectIsStatus2NamingTheKeyAndItsPosition) {
  const fs::path d = scratch("dup");
  const std::string scenario = write(d / "s.json", "{\"map_size\": 10,\n \"robots\": [[0.5, 0.5]], \"map_size\": 12}");
  expect_one_error_line(run_binary(kBin, "run " + scenario),
                        scenario + ":2:26: the key \"map_size\" appears twice in one object");
  // The same key in two objects is fine; an escaped spelling of the same key is the same key.
  const std::string ok = write(d / "ok.json", "{\"map_size\": 4, \"robots\": [[0.5, 0.5]], \"params\": {\"s_range\": 1}}");
  EXPECT_NE(run_binary(kBin, "run --steps 2 " + ok).status, 2);
  const std::string escaped = write(d / "e.json", "{\"map_size\": 4, \"robots\": [[0.5, 0.5]], \"map_\\u0073ize\": 5}");
  expect_one_error_line(run_binary(kBin, "run " + escaped), "appears twice");
}

TEST(Limits, ADeviceOrAFolderAsInputIsRefusedInsteadOfReadForEver) {
  const fs::path d = scratch("devices");
  for (const std::string& args : {std::string("run /dev/zero"), std::string("mission plan /dev/zero"),
                                  std::string("fsm check /dev/zero"), std::string("replay /dev/zero"),
                                  std::string("view /dev/zero -o ") + (d / "v.html").string()})
    expect_one_error_line(run_binary(kBin, args), "/dev/zero: is a character device, not a file");
  expect_one_error_line(run_binary(kBin, "run " + d.string()), d.string() + ": is a folder");
  expect_one_error_line(run_binary(kBin, "replay " + d.string()), d.string() + ": is a folder");
  // A named pipe nobody writes to reads as empty (one message), not a hang; replay reads its
  // trace twice, so it wants a regular file.
  const std::string fifo = (d / "p.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_one_error_line(run_binary(kBin, "run " + fifo), fifo + ":1:1: not valid JSON");
  expect_one_error_line(run_binary(kBin, "replay " + fifo), fifo + ": is a pipe");
  EXPECT_TRUE(temp_files(d).empty());
}

TEST(Limits, AFifoOrADeviceAsOutputIsRefusedAndASymlinkIsWrittenThrough) {
  const fs::path d = scratch("outputs");
  const std::string fifo = (d / "out.jsonl").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_one_error_line(run_binary(kBin, "run --steps 2 --trace " + fifo), fifo + ": is a FIFO (named pipe), not a regular file");
  expect_one_error_line(run_binary(kBin, "run --steps 2 --trace /dev/null"), "/dev/null: is a device, not a regular file");
  expect_one_error_line(run_binary(kBin, "run --steps 2 --trace " + d.string()), d.string() + ": is a folder");
  EXPECT_TRUE(fs::is_fifo(fifo));
  const std::string target = write(d / "target.jsonl", "old");
  const fs::path link = d / "link.jsonl";
  fs::create_symlink(target, link);
  EXPECT_EQ(run_binary(kBin, "run --steps 2 --trace " + link.string()).status, 1);   // max_steps: not completed
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read(target).rfind("{\"format\":\"swarmcheck-trace\"", 0), 0U);
  // A link to a file not made yet: the file is made where it points, the link stays.
  const fs::path dangling = d / "dangling.jsonl";
  fs::remove(dangling);
  fs::remove(d / "made.jsonl");
  fs::create_symlink("made.jsonl", dangling);
  EXPECT_EQ(run_binary(kBin, "run --steps 2 --trace " + dangling.string()).status, 1);
  EXPECT_TRUE(fs::is_symlink(dangling));
  EXPECT_EQ(read(d / "made.jsonl").rfind("{\"format\":\"swarmcheck-trace\"", 0), 0U);
  // Two links deep: both stay.
  for (const char* name : {"first.jsonl", "second.jsonl", "end.jsonl"}) fs::remove(d / name);
  fs::create_symlink("second.jsonl", d / "first.jsonl");
  fs::create_symlink("end.jsonl", d / "second.jsonl");
  EXPECT_EQ(run_binary(kBin, "run --steps 2 --trace " + (d / "first.jsonl").string()).status, 1);
  EXPECT_TRUE(fs::is_symlink(d / "first.jsonl"));
  EXPECT_TRUE(fs::is_symlink(d / "second.jsonl"));
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(d / "end.jsonl")));
  EXPECT_TRUE(temp_files(d).empty());
}

// A long run writing a trace, interrupted: the old trace keeps its bytes, the temporary file is
// removed, and the status is 128 + the signal.
TEST(Limits, SigintAndSigtermLeaveTheOldTraceAndNoTemporaryFileAndExit130Or143) {
  const fs::path d = scratch("signals");
  const std::string scenario =
      write(d / "s.json", R"({"map_size": 300, "robots": [[0.5, 0.5], [10.5, 10.5]], "mode": "abstract", "max_steps": 100000000})");
  const std::string trace = write(d / "t.jsonl", "the old trace");
  for (const int sig : {SIGINT, SIGTERM}) {
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::signal(SIGINT, SIG_DFL);
      ::signal(SIGTERM, SIG_DFL);
      const int devnull = ::open("/dev/null", O_WRONLY);
      ::dup2(devnull, 1);
      ::dup2(devnull, 2);
      ::execl(kBin.c_str(), kBin.c_str(), "run", scenario.c_str(), "--trace", trace.c_str(), "--stall-window", "0",
              "--max-trace-bytes", "0", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // Wait until the run is writing (its temporary file exists), then interrupt it.
    for (int k = 0; k < 200 && temp_files(d).empty(); ++k) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    EXPECT_FALSE(temp_files(d).empty());
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    ::kill(pid, sig);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of exiting";
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
    EXPECT_EQ(read(trace), "the old trace");
    EXPECT_TRUE(temp_files(d).empty());
  }
}

TEST(Limits, AMapThatCannotFitIsRefusedBeforeAnythingIsAllocatedWithALimitThatWouldFit) {
  const fs::path d = scratch("memory");
  const std::string scenario = write(d / "s.json", R"({"map_size": 65536, "robots": [[0.5, 0.5]]})");
  expect_one_error_line(run_binary(kBin, "run " + scenario + " --memory-limit 16G"),
                        scenario + ": a 65536 x 65536 map with 1 robots needs about 64.0 GiB, over the limit of 16.0 GiB "
                        "(raise it with --memory-limit, e.g. --memory-limit 65G, or make the input smaller)");
  // A trace whose header names such a map: replay refuses it at the header, not with "out of memory".
  const std::string trace = (d / "t.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "run --steps 2 --trace " + trace).status, 1);
  std::string text = read(trace);
  text.replace(text.find("\"map_size\":10"), 13, "\"map_size\":65536");
  const std::string huge = write(d / "huge.jsonl", text);
  expect_one_error_line(run_binary(kBin, "replay " + huge + " --memory-limit 16G"),
                        huge + ":1: the trace's 65536 x 65536 map with 4 robots needs about");
  const std::string small = write(d / "small.json", R"({"map_size": 1024, "robots": [[0.5, 0.5]]})");
  expect_one_error_line(run_binary(kBin, "run " + small + " --memory-limit 1M"), "over the limit of 1.0 MiB");
  // The estimate counts the process itself (about 15 MiB): the default 10 x 10 fits in 16M, not 1M.
  EXPECT_EQ(run_binary(kBin, "run --steps 1 --memory-limit 16M").status, 1);
  expect_one_error_line(run_binary(kBin, "run --steps 1 --memory-limit 1M"), "over the limit of 1.0 MiB");
  const auto bad = run_binary(kBin, "run --memory-limit 12Q");   // a usage error, with the usual prefix
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.out.rfind("swarmcheck: error: --memory-limit: expected a size such as 8G, 512M, 1.5T or a number of bytes (0: no limit), got \"12Q\"", 0), 0U) << bad.out;
}

// A DSE point's map that cannot fit (map_size is a knob) is refused before the sweep, naming the
// point; points that fit alone but not together on every thread say so.
TEST(Limits, ADsePointThatCannotFitIsRefusedBeforeTheSweepNamingThePoint) {
  const fs::path d = scratch("dse-memory");
  const std::string config = write(d / "big.dse.json", R"({"algorithm": {"type": "exhaustive"},
    "parameters": {"map_size": [64, 65536]},
    "objectiveDefinitions": {"internalFunctions": {"eP": {"columnID": "eP", "objectiveType": "max"}}},
    "ranking": {"pareto": {"eP": "+"}}})");
  const std::string out = (d / "out").string();
  expect_one_error_line(run_binary(kBin, "dse " + config + " -o " + out + " --memory-limit 16G --threads 1"),
                        config + ": design point map_size=65536: a 65536 x 65536 map with 4 robots needs about 64.0 GiB, "
                        "over the limit of 16.0 GiB (raise it with --memory-limit, e.g. --memory-limit 65G");
  EXPECT_FALSE(fs::exists(out));
  const std::string two = write(d / "two.dse.json", R"({"algorithm": {"type": "exhaustive"},
    "parameters": {"map_size": [64, 8192]},
    "objectiveDefinitions": {"internalFunctions": {"eP": {"columnID": "eP", "objectiveType": "max"}}},
    "ranking": {"pareto": {"eP": "+"}}})");
  const std::string both = write(d / "both.dse.json", R"({"algorithm": {"type": "exhaustive"},
    "parameters": {"map_size": [8192, 8190]},
    "objectiveDefinitions": {"internalFunctions": {"eP": {"columnID": "eP", "objectiveType": "max"}}},
    "ranking": {"pareto": {"eP": "+"}}})");
  if (std::thread::hardware_concurrency() >= 2)
    expect_one_error_line(run_binary(kBin, "dse " + both + " -o " + out + " --memory-limit 1500M --threads 2"),
                          "design point map_size=8192: a 8192 x 8192 map with 4 robots, with the 2 largest points at once "
                          "(--threads 2; --threads 1 runs one at a time) needs about 2.0 GiB");

  expect_one_error_line(run_binary(kBin, "dse " + two + " -o " + out + " --memory-limit 900M --threads 1"),
                        "a 8192 x 8192 map with 4 robots needs about 1.0 GiB");
  EXPECT_FALSE(fs::exists(out));
}

// The default limit is 3/4 of what the process may have: under `ulimit -v` a map that the
// machine could hold but the process cannot is refused with the limit, not "out of memory".
TEST(Limits, TheDefaultMemoryLimitFollowsUlimitV) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of shadow memory, which ulimit -v forbids (the release build runs this)";
#endif
  const fs::path d = scratch("ulimit");
  const std::string scenario = write(d / "s.json", R"({"map_size": 16384, "robots": [[0.5, 0.5]]})");
  const auto r = run_binary("ulimit -v 2000000; " + kBin, "run " + scenario);   // 1.9 GiB of address space
  expect_one_error_line(r, scenario + ": a 16384 x 16384 map with 1 robots needs about 4.0 GiB, over the limit of 1.4 GiB");
}

TEST(Limits, AProductOverTheMemoryLimitStopsCleanlyWithTheStatesExplored) {
  const fs::path d = scratch("product");
  const std::string c2 = kSource + "/scenarios/thesis/control2.fsm";
  const std::string out = write(d / "p.fsm", "old");
  const auto r = run_binary(kBin, "fsm product " + c2 + " " + c2 + " -o " + out + " --memory-limit 100");
  expect_one_error_line(r, "the product stopped after exploring 0 states (1 found");
  EXPECT_NE(r.out.find("raise it with --memory-limit"), std::string::npos);
  EXPECT_EQ(read(out), "old");
  const auto s = run_binary(kBin, "fsm synth --plant " + c2 + " --spec " + c2 + " -o " + out + " --memory-limit 100");
  expect_one_error_line(s, "the product stopped after exploring");
  EXPECT_EQ(run_binary(kBin, "fsm product " + c2 + " " + c2 + " -o " + out).status, 0);
}

// An automaton of n + 2 states whose observer has 2^n classes: from 0, an unobservable u guesses
// that the a just coming is the n-th last observed event (the classic blow-up of determinising).
std::string exponential_observer_fsm(int n) {
  std::string t = std::to_string(n + 2) + "\n\n0 1 3\na 0 c o\nb 0 c o\nu g uc uo\n\ng 1 1\na 1 c o\n";
  for (int i = 1; i < n; ++i)
    t += "\n" + std::to_string(i) + " 1 2\na " + std::to_string(i + 1) + " c o\nb " + std::to_string(i + 1) + " c o\n";
  return t + "\n" + std::to_string(n) + " 1 0\n";
}

TEST(Limits, AnObserverOverTheMemoryLimitStopsProjectAndNormalSynthesisCleanly) {
  const fs::path d = scratch("observer");
  const std::string plant = write(d / "guess.fsm", exponential_observer_fsm(22));
  const std::string spec = write(d / "all.fsm", "1\n\ns 1 3\na s c o\nb s c o\nu s uc uo\n");
  const std::string out = write(d / "out.fsm", "old");
  expect_one_error_line(run_binary(kBin, "fsm project " + plant + " -o " + out + " --memory-limit 20M"),
                        plant + ": the observer stopped after ");
  expect_one_error_line(run_binary(kBin, "fsm synth --plant " + plant + " --spec " + spec + " -o " + out + " --memory-limit 20M"),
                        plant + " || " + spec + ": the observer stopped after ");
  EXPECT_EQ(read(out), "old");
  // Small enough, both run: 2^8 classes.
  const std::string small = write(d / "guess8.fsm", exponential_observer_fsm(8));
  const auto r = run_binary(kBin, "fsm project " + small + " -o " + out + " --json --memory-limit 20M");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\"states\": 256"), std::string::npos) << r.out;
}

TEST(Limits, ATraceEstimatedOverTheLimitIsRefusedBeforeTheRunStarts) {
  const fs::path d = scratch("trace-size");
  const std::string mission = kSource + "/scenarios/thesis/thesis-mission.json";
  const std::string trace = write(d / "t.jsonl", "old");
  expect_one_error_line(run_binary(kBin, "mission run " + mission + " --dt 1e-4 --max-time 1e7 --trace " + trace),
                        "the trace of --max-time 1e+07 s at --dt 0.0001 s (1e+11 steps) needs about");
  expect_one_error_line(run_binary(kBin, "run --steps 1000000000 --trace " + trace),
                        "the trace (1000000000 steps at most) needs about");
  const auto r = run_binary(kBin, "run --steps 1000 --trace " + trace + " --max-trace-bytes 10K");
  expect_one_error_line(r, "over the limit of 10.0 KiB (raise it with --max-trace-bytes");
  EXPECT_EQ(read(trace), "old");
  EXPECT_TRUE(temp_files(d).empty());
}

TEST(Limits, MissionCoordinatesBeyondABillionMetresAreRefusedNotTurnedIntoInfinity) {
  const fs::path d = scratch("coordinates");
  for (const std::string x : {"1e200", "-1e155", "1000000001"})
    expect_one_error_line(run_binary(kBin, "mission plan " + mission_with_task_at(d, x)),
                          "tasks[0].at: expected finite coordinates in metres, each within +-1e9");
  EXPECT_EQ(run_binary(kBin, "mission plan " + mission_with_task_at(d, "1000")).status, 0);
}

TEST(Limits, AnFsmNameThatIsNotUtf8IsStatus2AtItsLineAndNeverBreaksJsonOutput) {
  const fs::path d = scratch("utf8");
  const std::string fsm = write(d / "u.fsm", "1\n\ns\xff" "1\t0\t1\na\ts\xff" "1\tc\to\n");
  for (const std::string& args : {"fsm check " + fsm, "fsm check --json " + fsm, "fsm export " + fsm + " --to json"})
    expect_one_error_line(run_binary(kBin, args), fsm + ":3:2: a name that is not valid UTF-8 text (byte 255)");
  // A path that is not UTF-8 is printed with U+FFFD in JSON, not an internal error.
  const fs::path odd = d / "odd\xff.fsm";
  fs::copy_file(kSource + "/scenarios/thesis/control2.fsm", odd);
  const auto r = run_binary(kBin, "fsm check --json '" + odd.string() + "'");
  EXPECT_NE(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("odd\xEF\xBF\xBD.fsm"), std::string::npos) << r.out;
}

TEST(Limits, ControlBytesAndLongExcerptsInAMessageArePrintedEscapedOnOneShortLine) {
  const fs::path d = scratch("messages");
  const std::string scenario = write(d / "s.json", R"({"map_size": 4, "robots": [[0.5, 0.5]], "rule": "two\nlines\u001b[2J"})");
  const auto r = run_binary(kBin, "run " + scenario);
  expect_one_error_line(r, "two\\x0Alines\\x1B[2J");
  const std::string unclosed = write(d / "u.json", "{\"map_size\": \"" + std::string(5000, 'x'));
  const auto u = run_binary(kBin, "run " + unclosed);
  expect_one_error_line(u, "more bytes)");
  EXPECT_LT(u.out.size(), 600U);
}

TEST(Limits, AWalledInCellIsReportedAndTheRunStopsAsStalledWithStatus1) {
  const fs::path d = scratch("walled");
  // Cell (0, 0) is walled in by obstacles; the robot starts in the far corner.
  const std::string scenario = write(
      d / "s.json", R"({"map_size": 6, "robots": [[5.5, 5.5]], "obstacles": [[0, 1], [1, 0], [1, 1]], "mode": "abstract"})");
  const auto r = run_binary(kBin, "run " + scenario + " --json");
  EXPECT_EQ(r.status, 1) << r.out;
  ASSERT_NE(r.out.find("\n{"), std::string::npos) << r.out;   // the warning, then the summary
  const auto j = nlohmann::json::parse(r.out.substr(r.out.find("\n{") + 1));
  EXPECT_EQ(j["unreachable_cells"], 1);
  EXPECT_EQ(j["reachable_cells"], 32);
  EXPECT_EQ(j["visited"], 32);
  EXPECT_EQ(j["eP_reachable"], 100.0);
  EXPECT_EQ(j["outcome"], "stalled");
  EXPECT_EQ(j["stalled"], "every reachable free cell is visited; 1 free cells are unreachable");
  const auto text = run_binary(kBin, "run " + scenario);
  EXPECT_NE(text.out.find("warning: 1 of 33 free cells cannot be reached by any robot"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("stalled after"), std::string::npos) << text.out;
  // No progress for the window: in cosim mode a robot drives several steps between cells.
  const auto w = run_binary(kBin, "run --stall-window 3 --json");
  EXPECT_EQ(w.status, 1) << w.out;
  EXPECT_EQ(nlohmann::json::parse(w.out)["stalled"], "no newly visited cell in the last 3 steps (--stall-window)");
  const auto ok = run_binary(kBin, "run --json");
  EXPECT_EQ(ok.status, 0);
  EXPECT_EQ(nlohmann::json::parse(ok.out)["outcome"], "completed");
}

TEST(Limits, ReplayRefusesARepeatedRecordAndATraceWithNoRecords) {
  const fs::path d = scratch("replay");
  const std::string trace = (d / "t.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "run --steps 3 --trace " + trace).status, 1);
  const std::string whole = read(trace);
  const std::size_t line2 = whole.find('\n') + 1, line3 = whole.find('\n', line2) + 1;
  const std::string twice = write(d / "twice.jsonl", whole.substr(0, line3) + whole.substr(line2, line3 - line2) + whole.substr(line3));
  expect_one_error_line(run_binary(kBin, "replay " + twice), twice + ":3: records are not in increasing step order (step 0 after step 0)");
  const std::string header = write(d / "header.jsonl", whole.substr(0, line2));
  expect_one_error_line(run_binary(kBin, "replay " + header), header + ": no step records after the header");
  const std::string typed = write(d / "typed.jsonl", "{\"format\": 1}\n");
  expect_one_error_line(run_binary(kBin, "replay " + typed), typed + ":1: header: format: expected \"swarmcheck-trace\"");
}

TEST(Limits, TheHelpStatesTheExitStatuses) {
  const auto r = run_binary(kBin, "--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("Exit status: 0 ok; 1 a negative verdict"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("130 / 143 / 129 interrupted by SIGINT / SIGTERM / SIGHUP"), std::string::npos) << r.out;
}
