// The view / edit / serve verbs from the outside: bad input gets exit status 2, the message the
// other verbs give, and no output file; good input writes one self-contained page.
#include <gtest/gtest.h>

#include <filesystem>
#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/util/shell.hpp"

using swarmcheck::testing::run_binary;
namespace fs = std::filesystem;

namespace {

const std::string kBin = SWARMCHECK_BIN;
const std::string kSource = SWARMCHECK_SOURCE_DIR;

fs::path scratch() {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck-views-cli-" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

std::string write(const fs::path& p, const std::string& text) {
  std::ofstream(p) << text;
  return p.string();
}

}  // namespace

TEST(ViewsCli, EditRefusesWhatRunRefusesWithTheSameMessageAndWritesNothing) {
  const fs::path d = scratch();
  const std::string bad = write(d / "bad.json", R"({"map_size": 4, "robots": [[0.5, 0.5], [0.6, 0.5]]})");
  const auto run = run_binary(kBin, "run " + bad);
  const auto edit = run_binary(kBin, "edit " + bad + " -o " + (d / "e.html").string());
  EXPECT_EQ(run.status, 2);
  EXPECT_EQ(edit.status, 2);
  EXPECT_EQ(edit.out, run.out);
  EXPECT_FALSE(fs::exists(d / "e.html"));
  const auto bad_mission = run_binary(kBin, "edit " + write(d / "m.json", R"({"fsm": "none.fsm"})") + " -o " + (d / "m.html").string());
  EXPECT_EQ(bad_mission.status, 2) << bad_mission.out;
  EXPECT_FALSE(fs::exists(d / "m.html"));
}

TEST(ViewsCli, ViewOfABadTraceIsStatus2WithNoPartialOutputAndKeepsAnOldFile) {
  const fs::path d = scratch();
  const std::string out = (d / "v.html").string();
  write(out, "old");
  const std::string bad = write(d / "t.jsonl", "{\"format\":\"swarmcheck-trace\",\"system\":\"exploration\"}\n");
  const auto r = run_binary(kBin, "view " + bad + " -o " + out);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "swarmcheck: error: " + bad + ":1: the header has no \"scenario\"\n");
  std::ifstream in(out);
  std::string kept((std::istreambuf_iterator<char>(in)), {});
  EXPECT_EQ(kept, "old");
  const auto broken_proof = run_binary(kBin, "view " + write(d / "h.jsonl", "{\"format\":\"swarmcheck-trace\",\"system\":\"handshake\"}\n{}\n") + " -o " + out);
  EXPECT_EQ(broken_proof.status, 2) << broken_proof.out;
}

TEST(ViewsCli, TraceFieldWritesFormat2WhichReplayStillReproduces) {
  const fs::path d = scratch();
  const std::string trace = (d / "f.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "run --mode abstract --trace " + trace + " --trace-field 7").status, 0);
  std::ifstream in(trace);
  std::string line;
  std::getline(in, line);
  EXPECT_NE(line.find("\"format_version\":2"), std::string::npos);
  EXPECT_NE(line.find("\"field_every\":7"), std::string::npos);
  int fields = 0, records = 0;
  while (std::getline(in, line)) (line.rfind("{\"type\":\"field\"", 0) == 0 ? fields : records) += 1;
  EXPECT_EQ(fields, (records - 1) / 7 + 1 + ((records - 1) % 7 != 0 ? 1 : 0));   // every 7th step and the last
  const auto replay = run_binary(kBin, "replay " + trace);
  EXPECT_EQ(replay.status, 0) << replay.out;
  EXPECT_NE(replay.out.find("agree bit for bit"), std::string::npos) << replay.out;
  const auto no_trace = run_binary(kBin, "run --trace-field 5");
  EXPECT_EQ(no_trace.status, 2);
  EXPECT_EQ(no_trace.out, "swarmcheck: error: --trace-field: needs --trace FILE\n");
}

TEST(ViewsCli, PicturesAreWrittenForRunsMissionsAndAutomata) {
  const fs::path d = scratch();
  EXPECT_EQ(run_binary(kBin, "run --mode abstract --svg " + (d / "r.svg").string()).status, 0);
  EXPECT_EQ(run_binary(kBin, "mission run " + kSource + "/scenarios/thesis/thesis-mission.json --body kinematic --svg " + (d / "m.svg").string()).status, 0);
  EXPECT_EQ(run_binary(kBin, "fsm export " + kSource + "/scenarios/thesis/control2.fsm --to svg -o " + (d / "f.svg").string()).status, 0);
  for (const char* f : {"r.svg", "m.svg", "f.svg"}) {
    std::ifstream in(d / f);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    EXPECT_EQ(text.rfind("<svg", 0), 0u) << f;
    EXPECT_NE(text.find("</svg>"), std::string::npos) << f;
  }
}

// A mission trace is checked against its mission: every event a transition of the mission's FSM
// from the state the events before led to, of the robot its meaning names, with the FSM's kind;
// every step in the state the events led to. An edited trace is status 2 at its line.
TEST(ViewsCli, AMissionTraceThatIsNotARunOfItsMissionIsStatus2AtTheLine) {
  const fs::path d = scratch() / "mission-trace";
  fs::create_directories(d);
  const std::string trace = (d / "m.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "mission run " + kSource + "/scenarios/thesis/thesis-mission.json --body kinematic --trace " + trace).status, 0);
  std::stringstream buffer;
  buffer << std::ifstream(trace).rdbuf();
  const std::string good = buffer.str();
  const std::string out = (d / "m.html").string();
  ASSERT_EQ(run_binary(kBin, "view " + trace + " --mission " + kSource + "/scenarios/thesis/thesis-mission.json -o " + out).status, 0);
  // Line 3 of the thesis mission's trace: {"type":"event","t":0.0,"event":"b8e","robot":"B","kind":"uc","state":"s4"}
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return write(d / "edited.jsonl", text);
  };
  const auto refused = [&](const std::string& file, const std::string& part) {
    const auto r = run_binary(kBin, "view " + file + " --mission " + kSource + "/scenarios/thesis/thesis-mission.json -o " + (d / "e.html").string());
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(part), std::string::npos) << "expected \"" << part << "\" in: " << r.out;
    EXPECT_FALSE(fs::exists(d / "e.html"));
  };
  const std::string b8e = R"("event":"b8e","robot":"B","kind":"uc","state":"s4")";
  refused(edited(b8e, R"("event":"b8x","robot":"B","kind":"uc","state":"s4")"), "edited.jsonl:3: event: \"b8x\" is not an event of control2.fsm");
  refused(edited(b8e, R"("event":"b8e","robot":"A","kind":"uc","state":"s4")"), "edited.jsonl:3: robot: expected \"B\"");
  refused(edited(b8e, R"("event":"b8e","robot":"B","kind":"c","state":"s4")"), "edited.jsonl:3: kind: expected \"uc\"");
  refused(edited(b8e, R"("event":"b8e","robot":"B","kind":"uc","state":"s9")"), "edited.jsonl:3: state: expected \"s4\"");
  refused(edited(R"("event":"a5e")", R"("event":"b8e")"), "edited.jsonl:2: robot: expected \"B\"");
  refused(edited(R"("robots":["A","B"])", R"("robots":["B","A"])"), "edited.jsonl:1: robots[0]: expected \"A\"");
  refused(edited(R"({"type":"step","t":0.05,"state":")", R"({"type":"step","t":0.05,"state":"x)"), ": state: expected");
}

TEST(ViewsCli, ServeRefusesABadPort) {
  const auto r = run_binary(kBin, "serve --port 70000");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, "swarmcheck: error: --port: expected an integer in [0, 65535], got 70000\n");
}

TEST(ViewsCli, ViewOfADseFolderIsItsReportAndAnyOtherFolderIsStatus2) {
  const fs::path d = scratch();
  const std::string dse = (d / "dse").string();
  const auto sweep = run_binary(kBin, "dse " + kSource + "/scenarios/thesis/dse/ertu.dse.json --scenario " + kSource +
                                          "/scenarios/thesis/dse/base.json -o " + dse);
  ASSERT_EQ(sweep.status, 0) << sweep.out;
  const std::string out = (d / "dse-view.html").string();
  const auto view = run_binary(kBin, "view " + dse + " -o " + out);
  ASSERT_EQ(view.status, 0) << view.out;
  EXPECT_EQ(view.out, out + ": dse view of " + dse + " (8 design points)\n");
  std::ifstream page(out), report(dse + "/report.html");
  const std::string page_text((std::istreambuf_iterator<char>(page)), {});
  const std::string report_text((std::istreambuf_iterator<char>(report)), {});
  EXPECT_EQ(page_text, report_text);
  EXPECT_NE(page_text.find("Pareto"), std::string::npos);

  const fs::path other = d / "not-dse";
  fs::create_directories(other);
  const auto refused = run_binary(kBin, "view " + other.string() + " -o " + (d / "o.html").string());
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.out, "swarmcheck: error: " + other.string() +
                             ": a folder to view must be a `swarmcheck dse` output folder, with results.json\n");
  write(other / "results.json", R"({"format": "swarmcheck-trace"})");
  const auto wrong = run_binary(kBin, "view " + other.string() + " -o " + (d / "o.html").string());
  EXPECT_EQ(wrong.status, 2) << wrong.out;
  EXPECT_FALSE(fs::exists(d / "o.html"));
}

TEST(ViewsCli, ADseFolderWithBrokenResultsOrAReportThatIsNotDsesIsStatus2NamingTheFile) {
  const fs::path d = scratch();
  const fs::path dse = d / "dse";
  const auto sweep = run_binary(kBin, "dse " + kSource + "/scenarios/thesis/dse/ertu.dse.json --scenario " + kSource +
                                          "/scenarios/thesis/dse/base.json -o " + dse.string());
  ASSERT_EQ(sweep.status, 0) << sweep.out;
  std::ifstream in(dse / "results.json");
  const std::string results((std::istreambuf_iterator<char>(in)), {});
  const std::string out = (d / "v.html").string();
  const auto refused = [&](const std::string& expected) {
    const auto r = run_binary(kBin, "view " + dse.string() + " -o " + out);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_FALSE(fs::exists(out));
  };
  const auto at = results.find("\"points\"");
  ASSERT_NE(at, std::string::npos);
  write(dse / "results.json", results.substr(0, at) + "\"points\": 3, \"was\"" + results.substr(at + 8));
  refused((dse / "results.json").string() + ": points: expected the list of design points");
  const auto first = results.find("\"parameters\"", at);
  ASSERT_NE(first, std::string::npos);
  write(dse / "results.json", results.substr(0, first) + "\"parameterz\"" + results.substr(first + 12));
  refused((dse / "results.json").string() + ": points[0]: expected a design point");
  write(dse / "results.json", results);
  write(dse / "report.html", "<html>something else</html>");
  refused((dse / "report.html").string() + ": expected the report `swarmcheck dse` writes");
}

// `view` opens no file that the command line did not name (issue 38): a mission trace's header
// names its mission, and view used to open that path as written (and echo its first byte in the
// error when it was not a mission). Now only the file of that name next to the trace is looked
// up, or the one --mission gives.
TEST(ViewsCli, AMissionTraceHeaderNamingAFileElsewhereDoesNotMakeViewOpenIt) {
  const fs::path d = scratch() / "mission-path";
  fs::create_directories(d / "elsewhere");
  fs::create_directories(d / "traces");
  const std::string secret = write(d / "elsewhere" / "secret.json", "Zsecret text that view must never read\n");
  const std::string mission = kSource + "/scenarios/thesis/thesis-mission.json";
  const std::string trace = (d / "traces" / "m.jsonl").string();
  ASSERT_EQ(run_binary(kBin, "mission run " + mission + " --body kinematic --trace " + trace).status, 0);
  std::stringstream buffer;
  buffer << std::ifstream(trace).rdbuf();
  std::string text = buffer.str();
  const std::string named = "\"mission\":\"" + mission + "\"";
  ASSERT_NE(text.find(named), std::string::npos) << text.substr(0, 300);
  text.replace(text.find(named), named.size(), "\"mission\":\"" + secret + "\"");
  write(trace, text);
  const auto r = run_binary(kBin, "view " + trace + " -o " + (d / "v.html").string());
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("is looked up next to the trace, as " + (d / "traces" / "secret.json").string()), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("'Z'"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("secret text"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(d / "v.html"));
  // The header's name next to the trace is the mission, and --mission names any file.
  fs::copy_file(mission, d / "traces" / "secret.json");
  fs::copy_file(kSource + "/scenarios/thesis/control2.fsm", d / "traces" / "control2.fsm");
  EXPECT_EQ(run_binary(kBin, "view " + trace + " -o " + (d / "v.html").string()).status, 0);
  EXPECT_EQ(run_binary(kBin, "view " + trace + " --mission " + mission + " -o " + (d / "w.html").string()).status, 0);
}
