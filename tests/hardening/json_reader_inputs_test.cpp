// Every JSON input through the one reader (spec/util/json_text.hpp; issue 38): the inputs that
// were parsed with nlohmann's parser directly, and crashed or accepted what every other input
// refuses. Each case failed before: replay and dse died with SIGSEGV, cosim died and left its
// unpacked FMUs in TMPDIR, or accepted an unknown member, or exited 3.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tests/util/shell.hpp"

namespace fs = std::filesystem;
using swarmcheck::testing::run_binary;
using swarmcheck::testing::ShellResult;

namespace {

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-json-reader-" + std::to_string(::getpid())) / name;
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

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

void expect_refused(const ShellResult& r, const std::string& part) {
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out.rfind("swarmcheck: error: ", 0), 0U) << r.out;
  EXPECT_NE(r.out.find(part), std::string::npos) << "expected \"" << part << "\" in: " << r.out;
}

TEST(JsonReaderInputs, ATraceHeaderNested200000DeepIsStatus2AtItsBracketNotACrash) {
  const fs::path d = scratch("replay");
  const std::string trace = (d / "t.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "run --steps 3 --trace " + trace).status, 1);
  std::string text = read(trace);
  text.insert(1, "\"deep\": " + nested(200000) + ", ");   // before the header's own members
  write(trace, text);
  // The header object is the first level: its member's 512th bracket is the 513th, at column 1 + 8 + 512.
  expect_refused(run_binary(kBin, "replay " + trace), trace + ":1:521: nested deeper than 512");
}

TEST(JsonReaderInputs, ADseJournalLineNested300000DeepIsSkippedOnResumeNotACrash) {
  const fs::path d = scratch("dse");
  const std::string config = kSource + "/scenarios/thesis/dse/ertu.dse.json";
  const std::string base = kSource + "/scenarios/thesis/dse/base.json";
  const fs::path out = d / "out";
  ASSERT_EQ(run_binary(kBin, "dse " + config + " --scenario " + base + " -o " + out.string()).status, 0);
  const std::string results = read(out / "results.csv");
  std::ofstream(out / "journal.jsonl", std::ios::app) << "{\"key\": " << nested(300000) << "}\n";
  const auto r = run_binary(kBin, "dse " + config + " --scenario " + base + " -o " + out.string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("8 points from the journal"), std::string::npos) << r.out;
  EXPECT_EQ(read(out / "results.csv"), results);
}

// The thesis multi-model, exported once, with Environment.fmu's resources/swarmcheck-fmu.json
// replaceable; cosim runs with TMPDIR inside the test's folder, so what it leaves can be seen.
class FmuResource : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch("cosim");
    ASSERT_EQ(run_binary(kBin, "fmu export --intocps " + (dir_ / "mm").string()).status, 0);
    std::string coe = read(dir_ / "mm" / "coe.json");
    {
      const std::size_t at = coe.find("\"endTime\": ") + 11;   // the exported end, whatever it is
      coe.replace(at, coe.find_first_of(",\n", at) - at, "1");   // ten steps
    }
    write(dir_ / "mm" / "coe.json", coe);
    fs::create_directories(dir_ / "unpacked");
    ASSERT_EQ(std::system(("cd " + (dir_ / "unpacked").string() + " && unzip -q " + (dir_ / "mm" / "Environment.fmu").string()).c_str()), 0);
    original_ = read(dir_ / "unpacked" / "resources" / "swarmcheck-fmu.json");
  }
  // Environment.fmu with `resource` as its resources/swarmcheck-fmu.json.
  static void with_resource(const std::string& text) {
    write(dir_ / "unpacked" / "resources" / "swarmcheck-fmu.json", text);
    fs::remove(dir_ / "mm" / "Environment.fmu");
    ASSERT_EQ(std::system(("cd " + (dir_ / "unpacked").string() + " && zip -q -r " + (dir_ / "mm" / "Environment.fmu").string() + " .").c_str()), 0);
  }
  static ShellResult cosim(const std::string& config = "") {
    const fs::path tmp = dir_ / "tmp";
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    return run_binary("TMPDIR=" + tmp.string() + " " + kBin,
                      "cosim " + (dir_ / "mm" / "multimodel.json").string() + " --config " +
                          (config.empty() ? (dir_ / "mm" / "coe.json").string() : config));
  }
  static bool tmp_empty() { return fs::is_empty(dir_ / "tmp"); }
  static inline fs::path dir_;
  static inline std::string original_;
};

TEST_F(FmuResource, TheUnmodifiedResourceRuns) {
  with_resource(original_);
  const auto r = cosim();
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(tmp_empty());
}

TEST_F(FmuResource, AResourceNested100000DeepIsStatus2NamingItAndLeavesNoFolderInTmpdir) {
  with_resource("{\"format\": \"swarmcheck-fmu-1\", \"x\": " + nested(100000) + "}");
  const auto r = cosim();
  expect_refused(r, "resources/swarmcheck-fmu.json:1:");
  EXPECT_NE(r.out.find("nested deeper than 512"), std::string::npos) << r.out;
  EXPECT_TRUE(tmp_empty()) << "unpacked FMU folders left in TMPDIR";
}

TEST_F(FmuResource, AnUnknownMemberIsRefusedAsInEveryOtherInputShallowOrNested600Deep) {
  std::string text = original_;
  text.insert(text.find('{') + 1, "\"colour\": \"red\", ");
  with_resource(text);
  expect_refused(cosim(), "resources/swarmcheck-fmu.json: colour: unknown key (expected one of: format, kind, interface, robots, obstacles, scenario)");
  text = original_;
  text.insert(text.find('{') + 1, "\"x\": " + std::string(600, '[') + "1" + std::string(600, ']') + ", ");
  with_resource(text);
  expect_refused(cosim(), "nested deeper than 512");
  EXPECT_TRUE(tmp_empty());
  with_resource(original_);
}

TEST_F(FmuResource, AnAlgorithmTypeThatIsNotAStringIsStatus2Not3) {
  with_resource(original_);
  for (const std::string type : {"5", "null", "[\"fixed-step\"]", "{}", "true"}) {
    const std::string config = write(dir_ / "coe-type.json", "{\"startTime\": 0, \"endTime\": 1, \"algorithm\": {\"type\": " + type + ", \"size\": 0.1}}");
    expect_refused(cosim(config), "coe-type.json: algorithm.type: expected \"fixed-step\"");
    EXPECT_TRUE(tmp_empty());
  }
}

}  // namespace
