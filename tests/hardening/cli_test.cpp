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
  const std::string mission = kSource + "/scenarios/thesis/thesis-mission.json";
  for (const std::string& seed : std::vector<std::string>{"-1", "18446744073709551616", "0x10"})
    EXPECT_EQ(run_binary(kBin, "mission run " + mission + " --max-time 1 --seed " + seed).status, 2) << seed;
}

TEST(Hardening, TheFsmAMissionNamesIsAnInputThatNoOutputMayReplace) {
  const fs::path d = scratch() / "mission-inputs";
  fs::create_directories(d);
  const std::string mission = (d / "m.json").string();
  fs::copy_file(kSource + "/scenarios/thesis/thesis-mission.json", mission, fs::copy_options::overwrite_existing);
  fs::copy_file(kSource + "/scenarios/thesis/control2.fsm", d / "control2.fsm", fs::copy_options::overwrite_existing);
  const std::string fsm = (d / "control2.fsm").string();
  const std::string before = read(fsm);
  const std::string trace = (d / "m.jsonl").string();
  ASSERT_NE(run_binary(kBin, "mission run " + mission + " --max-time 5 --trace " + trace).status, 2);
  for (const std::string& args : std::vector<std::string>{"mission run " + mission + " --max-time 5 --trace " + fsm,
                                 "mission run " + mission + " --max-time 5 --svg " + fsm,
                                 "edit " + mission + " -o " + fsm,
                                 "view " + trace + " --mission " + mission + " -o " + fsm,
                                 "view " + trace + " -o " + fsm,   // the mission its header names
                                 "view " + trace + " -o " + mission}) {
    const auto r = run_binary(kBin, args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_NE(r.out.find("is also an input of this command"), std::string::npos) << args << ": " << r.out;
  }
  EXPECT_EQ(read(fsm), before);
  const auto both = run_binary(kBin, "mission run " + mission + " --max-time 5 --trace " + trace + " --svg " + trace);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.out.find("is also the --trace output of this command: give --svg another file"), std::string::npos) << both.out;
  const std::string fresh = (d / "not-yet.jsonl").string();   // neither exists yet: same file by another name
  fs::remove(fresh);
  const auto renamed = run_binary(kBin, "run --steps 2 --trace " + fresh + " --svg " + (d / "." / "not-yet.jsonl").string());
  EXPECT_EQ(renamed.status, 2) << renamed.out;
  EXPECT_NE(renamed.out.find("is also the --trace output of this command"), std::string::npos) << renamed.out;
  EXPECT_FALSE(fs::exists(fresh));
}

TEST(Hardening, DseAndFmuOutputsThatAreInputsThroughALinkOrByNameAreRefusedBeforeAnythingRuns) {
  const fs::path d = scratch() / "dse-outputs";
  fs::remove_all(d);
  fs::create_directories(d / "linked");
  const std::string config = (d / "c.dse.json").string(), base = (d / "base.json").string();
  fs::copy_file(kSource + "/scenarios/thesis/dse/ertu.dse.json", config);
  fs::copy_file(kSource + "/scenarios/thesis/dse/base.json", base);
  const std::string base_before = read(base);
  for (const char* name : {"results.csv", "report.svg", "journal.jsonl"}) {
    fs::remove(d / "linked" / "results.csv");
    fs::remove(d / "linked" / "report.svg");
    fs::remove(d / "linked" / "journal.jsonl");
    fs::create_symlink(base, d / "linked" / name);
    const auto r = run_binary(kBin, "dse " + config + " --scenario " + base + " -o " + (d / "linked").string());
    EXPECT_EQ(r.status, 2) << name << ": " << r.out;
    EXPECT_NE(r.out.find("is also an input of this command"), std::string::npos) << r.out;
    EXPECT_EQ(read(base), base_before) << name;
  }
  fs::create_directories(d / "folder" / "results.csv");
  const auto folder = run_binary(kBin, "dse " + config + " --scenario " + base + " -o " + (d / "folder").string());
  EXPECT_EQ(folder.status, 2);
  EXPECT_NE(folder.out.find("results.csv: is a folder"), std::string::npos) << folder.out;
  EXPECT_FALSE(fs::exists(d / "folder" / "journal.jsonl"));   // refused before the sweep
  fs::create_directories(d / "fmus");
  fs::copy_file(base, d / "fmus" / "multimodel.json");
  const auto fmu = run_binary(kBin, "fmu export --intocps " + (d / "fmus").string() + " --scenario " + (d / "fmus" / "multimodel.json").string());
  EXPECT_EQ(fmu.status, 2) << fmu.out;
  EXPECT_EQ(read(d / "fmus" / "multimodel.json"), base_before);
  EXPECT_FALSE(fs::exists(d / "fmus" / "Environment.fmu"));
}

TEST(Hardening, APathThatIsNotUtf8IsWrittenIntoJsonWithTheReplacementCharacterNotAnInternalError) {
  const fs::path d = scratch() / "utf8-paths";
  fs::remove_all(d);
  fs::create_directories(d);
  const std::string config = (d / "c\xff.dse.json").string();
  fs::copy_file(kSource + "/scenarios/thesis/dse/ertu.dse.json", config);
  fs::copy_file(kSource + "/scenarios/thesis/dse/base.json", d / "base.json");
  const auto r = run_binary(kBin, "dse '" + config + "' --scenario " + (d / "base.json").string() + " -o " + (d / "out").string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(read(d / "out" / "results.json").find("c\xEF\xBF\xBD.dse.json"), std::string::npos);
  const std::string mission = (d / "m\xff.json").string();
  fs::copy_file(kSource + "/scenarios/thesis/thesis-mission.json", mission);
  fs::copy_file(kSource + "/scenarios/thesis/control2.fsm", d / "control2.fsm");
  const auto m = run_binary(kBin, "mission run '" + mission + "' --max-time 5 --trace " + (d / "m.jsonl").string());
  EXPECT_NE(m.status, 3) << m.out;
  EXPECT_NE(m.status, 2) << m.out;
}

TEST(Hardening, ConformRefusesAnOutFolderItCouldNotWriteBeforeRunningAnyCase) {
  const fs::path d = scratch();
  const std::string file = write(d / "plain-file", "x");
  for (const std::string& out : std::vector<std::string>{file, "/proc/no-such/folder"}) {
    const auto r = run_binary(kBin, "conform --system automata --cases 1 --out " + out);
    EXPECT_EQ(r.status, 2) << out << ": " << r.out;
    EXPECT_EQ(r.out.rfind("swarmcheck: error: " + out + ": ", 0), 0U) << r.out;
  }
  const fs::path fresh = d / "fresh" / "deeper";
  fs::remove_all(d / "fresh");
  EXPECT_EQ(run_binary(kBin, "conform --system automata --cases 1 --out " + fresh.string()).status, 0);
  EXPECT_FALSE(fs::exists(d / "fresh"));   // checked by making it, and nothing left when all agree
}

TEST(Hardening, ProveRefusesATimeoutThatIsNotANumberOfSecondsInRange) {
  for (const std::string& t : std::vector<std::string>{"nan", "0", "-1", "1e18", "inf"}) {
    const auto r = run_binary(kBin, "prove --only servo-saturation --timeout " + t);
    EXPECT_EQ(r.status, 2) << t << ": " << r.out;
    EXPECT_NE(r.out.find("--timeout: expected seconds in (0, 86400], got " + t), std::string::npos) << r.out;
  }
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

TEST(Hardening, AnUnknownVerbIsNamedWithTheVerbsThereAreAndEmptyOrSubByteValuesAreRefused) {
  const auto top = run_binary(kBin, "zzz");
  EXPECT_EQ(top.status, 2);
  EXPECT_EQ(top.out.rfind("swarmcheck: error: unknown verb 'zzz' for swarmcheck (the verbs: run, conform, replay, fsm,", 0), 0U) << top.out;
  const auto fsm = run_binary(kBin, "fsm zzz");
  EXPECT_EQ(fsm.status, 2);
  EXPECT_NE(fsm.out.find("unknown verb 'zzz' for swarmcheck fsm (the verbs: check, product,"), std::string::npos) << fsm.out;
  const auto limit = run_binary(kBin, "run --steps 1 --memory-limit 0.5");   // would truncate to 0: no limit at all
  EXPECT_EQ(limit.status, 2);
  EXPECT_NE(limit.out.find("--memory-limit: expected a size"), std::string::npos) << limit.out;
  const auto only = run_binary(kBin, "prove --only ''");   // not every obligation
  EXPECT_EQ(only.status, 2);
  EXPECT_NE(only.out.find("--only: expected an obligation's name, got nothing"), std::string::npos) << only.out;
  const auto bind = run_binary(kBin, "serve --port 0 --bind ''");
  EXPECT_EQ(bind.status, 2);
  EXPECT_NE(bind.out.find("--bind: expected an address"), std::string::npos) << bind.out;
}

TEST(Hardening, AnSvgExportOfMoreTransitionsThanDotLaysOutInReasonableTimeIsRefused) {
  const fs::path d = scratch();
  std::string text = "4002\n";
  for (int k = 0; k < 4002; ++k)
    text += "\ns" + std::to_string(k) + "\t" + (k == 4001 ? "1\t0\n" : "0\t1\na\ts" + std::to_string(k + 1) + "\tc\to\n");
  const std::string fsm = write(d / "chain4002.fsm", text);
  const std::string svg = (d / "chain.svg").string();
  fs::remove(svg);
  const auto r = run_binary(kBin, "fsm export " + fsm + " --to svg -o " + svg);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find(fsm + ": 4001 transitions, more than the 4000 that dot lays out"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(svg));
  EXPECT_EQ(run_binary(kBin, "fsm export " + fsm + " --to dot -o " + (d / "chain.dot").string()).status, 0);
}

TEST(Hardening, ATraceOfAnotherFormatVersionIsRefusedNotReadAsThisOne) {
  const fs::path d = scratch();
  const std::string trace = (d / "v.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "run --steps 2 --trace " + trace).status, 1);
  std::string text = read(trace);
  const std::string v1 = "\"format_version\":1,";
  ASSERT_NE(text.find(v1), std::string::npos);
  for (const std::string& v : {std::string("\"format_version\":99,"), std::string("\"format_version\":\"1\",")}) {
    std::string other = text;
    other.replace(other.find(v1), v1.size(), v);
    const std::string path = write(d / "other.jsonl", other);
    const auto r = run_binary(kBin, "replay " + path);
    EXPECT_EQ(r.status, 2) << v << ": " << r.out;
    EXPECT_NE(r.out.find(path + ":1: header: format_version: "), std::string::npos) << r.out;
  }
  EXPECT_EQ(run_binary(kBin, "replay " + trace).status, 0);
}

TEST(Hardening, AHandshakeTraceWithNoStepsOrImpossibleSettingsIsRefused) {
  const fs::path d = scratch() / "handshake";
  fs::remove_all(d);
  ASSERT_EQ(run_binary(kBin, "prove --only handshake-gauss-seidel --trace-dir " + d.string()).status, 0);
  const std::string trace = (d / "handshake-gauss-seidel.jsonl").string();
  const std::string text = read(trace);
  const std::string header = text.substr(0, text.find('\n') + 1);
  const auto refused = [&](const std::string& name, const std::string& content, const std::string& message) {
    const std::string path = write(d / name, content);
    for (const char* verb : {"replay ", "view "}) {
      const auto r = run_binary(kBin, verb + path + (std::string(verb) == "view " ? " -o " + (d / "v.html").string() : ""));
      EXPECT_EQ(r.status, 2) << verb << name << ": " << r.out;
      EXPECT_NE(r.out.find(message), std::string::npos) << verb << name << ": " << r.out;
    }
  };
  refused("header-only.jsonl", header, "no step records after the header");
  std::string negative = text;
  const std::size_t t = negative.find("\"tolerance\":");
  ASSERT_NE(t, std::string::npos);
  negative.insert(t + 12, "-");
  refused("negative.jsonl", negative, "\"tolerance\" must be a number >= 0");
  std::string unknown = text;
  const std::size_t c = unknown.find("\"controller\":\"spec\"");
  ASSERT_NE(c, std::string::npos);
  unknown.replace(c, 19, "\"controller\":\"zz\"");
  refused("controller.jsonl", unknown, "\"controller\" must be \"spec\" or \"late\"");
  EXPECT_FALSE(fs::exists(d / "v.html"));
}

TEST(Hardening, ANulByteInAJsonInputIsNamedWhereItIs) {
  const fs::path d = scratch();
  const std::string starts = write(d / "nul0.json", std::string("\0{}", 3));
  const auto r = run_binary(kBin, "run " + starts);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "swarmcheck: error: " + starts + ":1:1: not valid JSON: a NUL byte (a binary file?)\n");
  const std::string inside = write(d / "nul1.json", std::string("{\"map_size\": 4,\n \"robots\"\0", 26));
  const auto r2 = run_binary(kBin, "run " + inside);
  EXPECT_EQ(r2.status, 2);
  EXPECT_EQ(r2.out, "swarmcheck: error: " + inside + ":2:10: not valid JSON: a NUL byte (a binary file?)\n");
}

// One output that cannot be written (a folder where a file goes, a folder that does not exist)
// is found before any other output is replaced: the others keep their old content.
TEST(Hardening, AnOutputThatCannotBeWrittenIsFoundBeforeAnyOtherOutputIsReplaced) {
  const fs::path d = scratch() / "outputs-first";
  fs::create_directories(d);
  const std::string trace = write(d / "t.jsonl", "OLD");
  const auto mission = run_binary(kBin, "mission run " + kSource + "/scenarios/examples/walls.json --body kinematic --trace " +
                                            trace + " --svg " + (d / "missing" / "x.svg").string());
  EXPECT_EQ(mission.status, 2) << mission.out;
  EXPECT_NE(mission.out.find("x.svg: cannot write this file: its folder"), std::string::npos) << mission.out;
  EXPECT_EQ(read(trace), "OLD");
  const fs::path ic = d / "ic";
  fs::create_directories(ic / "coe.json");
  const std::string fmu = write(ic / "Environment.fmu", "OLD");
  const auto exported = run_binary(kBin, "fmu export --intocps " + ic.string());
  EXPECT_EQ(exported.status, 2) << exported.out;
  EXPECT_NE(exported.out.find("coe.json: is a folder; expected a file path for the output"), std::string::npos) << exported.out;
  EXPECT_EQ(read(fmu), "OLD");
  EXPECT_FALSE(fs::exists(ic / "Body.fmu"));
}
