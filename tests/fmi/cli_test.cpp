// `fmu export` and `cosim` from the outside: the README's commands work, and bad multi-models
// are exit status 2 with one message naming the file and JSON path (or the FMU's logged
// message), with no temporary folder left behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "tests/fmi/scratch.hpp"
#include "tests/util/shell.hpp"

namespace {

namespace fs = std::filesystem;
using swarmcheck::testing::run_binary;
using Json = nlohmann::ordered_json;

const std::string kBin = SWARMCHECK_BIN;

struct Folder {
  fs::path dir = swarmcheck::testing::fmi_scratch("cli");
  fs::path tmp = dir / "tmp";
  Folder() {
    fs::create_directories(tmp);
    const auto r = run_binary(kBin, "fmu export --intocps " + (dir / "mm").string());
    EXPECT_EQ(r.status, 0) << r.out;
  }
  ~Folder() { fs::remove_all(dir); }
  // Runs cosim with TMPDIR inside the test's folder, so what is left there can be seen.
  swarmcheck::testing::ShellResult cosim(const std::string& args) const {
    return run_binary("TMPDIR=" + tmp.string() + " " + kBin, "cosim " + args);
  }
  bool tmp_empty() const { return fs::is_empty(tmp); }
  Json multimodel() const { return Json::parse(std::ifstream(dir / "mm" / "multimodel.json")); }
  std::string write(const Json& j, const std::string& name) const {
    const fs::path p = dir / "mm" / name;
    std::ofstream(p) << j.dump(2);
    return p.string();
  }
};

}  // namespace

TEST(FmiCli, ExportWritesTheThreeFmusAndCosimRunsTheThesisMultiModelToCompletion) {
  Folder f;
  for (const char* kind : {"environment", "controller", "body"}) {
    const auto r = run_binary(kBin, std::string("fmu export ") + kind + " -o " + (f.dir / (std::string(kind) + ".fmu")).string());
    EXPECT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(fs::file_size(f.dir / (std::string(kind) + ".fmu")) > 1000);
  }
  const std::string csv = (f.dir / "outputs.csv").string();
  const auto r = f.cosim((f.dir / "mm" / "multimodel.json").string() + " --config " + (f.dir / "mm" / "coe.json").string() +
                         " -o " + csv + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json summary = Json::parse(r.out);
  EXPECT_EQ(summary["eP"], 100.0);
  EXPECT_EQ(summary["completion_step"], 10237);
  EXPECT_EQ(summary["handshake"], "held");
  // The engine's outputs.csv: time, step-size, the connected outputs sorted by name (4 robots:
  // 3 per Body, 4 per Controller, 2 per robot and 2 more of the Environment), a row at 0.
  std::ifstream in(csv);
  std::string header, first, second;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(header.rfind("time,step-size,{Body}.body1.robot_theta,{Body}.body1.robot_x,{Body}.body1.robot_y,{Body}.body2.", 0),
            0u) << header.substr(0, 120);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 2 + 4 * (3 + 4 + 2) + 2 - 1) << header;
  EXPECT_EQ(header.find(",{Environment}.environment.eP"), std::string::npos);   // not connected, not logged
  EXPECT_EQ(first.rfind("0.0,0.0,0.0,0.5,0.5,", 0), 0u) << first.substr(0, 80);   // robot 1 at (0.5, 0.5)
  EXPECT_EQ(second.rfind("0.1,0.1,", 0), 0u) << second.substr(0, 80);
  EXPECT_TRUE(f.tmp_empty());
}

TEST(FmiCli, GaussSeidelReportsTheStaleAcceptanceWithStatusOne) {
  Folder f;
  const auto r = f.cosim((f.dir / "mm" / "multimodel.json").string() + " --config " + (f.dir / "mm" / "coe.json").string() +
                         " --algorithm gauss-seidel");
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("handshake VIOLATED (fresh-acceptance)"), std::string::npos) << r.out;
}

TEST(FmiCli, BadMultiModelsAreStatusTwoWithTheJsonPathAndLeaveNoTemporaryFolder) {
  Folder f;
  const Json good = f.multimodel();
  struct Case {
    std::string what, expected;
    Json mm;
  };
  std::vector<Case> cases;
  {
    Json j = good;
    j["fmus"]["{Body}"] = "missing.fmu";
    cases.push_back({"a missing FMU", "missing.fmu: no such FMU file", j});
  }
  {
    Json j = good;
    j["connections"]["{Body}.body1.robot_x"].push_back("{Controller}.controller2.nonesuch");
    cases.push_back({"an unknown variable", "has no variable nonesuch", j});
  }
  {
    Json j = good;
    j["connections"]["{Body}.body2.robot_x"].push_back("{Controller}.controller1.x");
    cases.push_back({"an input connected twice", "input {Controller}.controller1.x is connected twice", j});
  }
  {
    Json j = good;
    j["connections"]["{Controller}.controller1.servoLeft"] = Json::array({"{Environment}.environment.onDestination1Input"});
    j["connections"]["{Controller}.controller1.onDestinationOutput"] = Json::array();
    cases.push_back({"a type mismatch", "type mismatch", j});
  }
  {
    Json j = good;
    j["parameters"]["{Environment}.environment.mapSize"] = 0;
    cases.push_back({"an FMU returning fmi2Error", "fmi2ExitInitializationMode returned fmi2Error: ", j});
  }
  {
    Json j = good;
    j["connections"]["{Nowhere}.x.y"] = Json::array({"{Body}.body1.servo_left_input"});
    cases.push_back({"an unknown FMU key", "connections.{Nowhere}.x.y: FMU {Nowhere} is not in \"fmus\"", j});
  }
  {
    Json j = good;
    j["connections"]["{Body}.body1.robot_x"] = Json::array({"{Controller}.controller1.onDestinationOutput"});
    cases.push_back({"an output used as an input", "not an input", j});
  }
  {
    Json j = good;
    j["paramters"] = j["parameters"];
    j.erase("parameters");
    cases.push_back({"a misspelt key", "paramters: unknown key: did you mean \"parameters\"?", j});
  }
  {
    Json j = good;
    j["connections"]["{Body}.body1\n.robot_x"] = Json::array({"{Controller}.controller1.x"});
    cases.push_back({"a newline in an instance name (a column of outputs.csv)", "expected a name without control characters", j});
  }
  for (std::size_t k = 0; k < cases.size(); ++k) {
    const std::string path = f.write(cases[k].mm, "bad" + std::to_string(k) + ".json");
    const auto r = f.cosim(path + " --config " + (f.dir / "mm" / "coe.json").string());
    EXPECT_EQ(r.status, 2) << cases[k].what << ": " << r.out;
    EXPECT_NE(r.out.find(cases[k].expected), std::string::npos) << cases[k].what << ": " << r.out;
    EXPECT_EQ(r.out.rfind("swarmcheck: error: ", 0), 0u) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_TRUE(f.tmp_empty()) << cases[k].what;
  }
  // Not an FMU at all, and a configuration of another algorithm.
  std::ofstream(f.dir / "mm" / "text.fmu") << "not a zip";
  Json j = good;
  j["fmus"]["{Body}"] = "text.fmu";
  auto r = f.cosim(f.write(j, "text.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("expected an FMU (a zip archive)"), std::string::npos) << r.out;
  std::ofstream(f.dir / "coe-bad.json") << R"({"algorithm": {"type": "var-step", "size": 0.1}})";
  r = f.cosim((f.dir / "mm" / "multimodel.json").string() + " --config " + (f.dir / "coe-bad.json").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("algorithm.type: expected \"fixed-step\""), std::string::npos) << r.out;
  // Configurations that would run something else than asked: a misspelt end (the default 10 s
  // ran), a step longer than the run (no step ran), the multi-model given as the configuration.
  const std::string mm = (f.dir / "mm" / "multimodel.json").string();
  for (const auto& [config, expected] : std::vector<std::pair<std::string, std::string>>{
           {R"({"endtime": 0.5, "algorithm": {"type": "fixed-step", "size": 0.1}})", "endtime: unknown key: did you mean \"endTime\"?"},
           {R"({"endTime": 0.5, "algorithm": {"type": "fixed-step", "sizee": 0.1, "size": 0.1}})", "algorithm.sizee: unknown key: did you mean \"size\"?"},
           {R"({"endTime": 0.5, "algorithm": {"type": "fixed-step", "size": 1e308}})", "algorithm.size: expected a step of at most endTime - startTime (0.5 s)"},
           {good.dump(), "is a multi-model (it has \"fmus\"), not a co-simulation configuration"}}) {
    std::ofstream(f.dir / "coe-odd.json") << config;
    r = f.cosim(mm + " --config " + (f.dir / "coe-odd.json").string());
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(expected), std::string::npos) << r.out;
  }
  EXPECT_TRUE(f.tmp_empty());
}

// A long co-simulation stopped by Ctrl-C or SIGTERM: the FMUs are unloaded and their unpacked
// folders removed, the old outputs.csv keeps its bytes, and the status is 128 + the signal.
TEST(FmiCli, SigintAndSigtermUnloadTheFmusLeaveNoFolderAndKeepTheOldOutput) {
  Folder f;
  Json coe = Json::parse(std::ifstream(f.dir / "mm" / "coe.json"));
  coe["endTime"] = 1e7;
  const std::string config = f.write(coe, "long-coe.json");
  const fs::path csv = f.dir / "outputs.csv";
  for (const int sig : {SIGINT, SIGTERM}) {
    std::ofstream(csv) << "the old outputs";
    const std::string cmd = "exec env TMPDIR=" + f.tmp.string() + " " + kBin + " cosim " +
                            (f.dir / "mm" / "multimodel.json").string() + " --config " + config + " -o " + csv.string() +
                            " >" + (f.dir / "err.txt").string() + " 2>&1";
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::signal(SIGINT, SIG_DFL);
      ::signal(SIGTERM, SIG_DFL);
      ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // Wait until the three FMUs are unpacked, then a little into the run.
    const auto unpacked = [&] { return std::distance(fs::directory_iterator(f.tmp), fs::directory_iterator{}); };
    for (int k = 0; k < 400 && unpacked() < 3; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(25));
    EXPECT_EQ(unpacked(), 3);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(pid, sig);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    std::ifstream err_file(f.dir / "err.txt");
    const std::string err((std::istreambuf_iterator<char>(err_file)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping: " << err;
    EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << err;
    EXPECT_NE(err.find("swarmcheck cosim: interrupted at t = "), std::string::npos) << err;
    EXPECT_TRUE(f.tmp_empty());
    std::ifstream in(csv);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), "the old outputs");
    for (const auto& e : fs::directory_iterator(f.dir))   // no temporary file of the output left
      EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
  }
}

TEST(FmiCli, ExportRefusesImpossibleRequestsWithStatusTwo) {
  Folder f;
  EXPECT_EQ(run_binary(kBin, "fmu export environment").status, 2);                        // no -o
  EXPECT_EQ(run_binary(kBin, "fmu export --robots 500 --intocps " + (f.dir / "x").string()).status, 2);   // 96 free cells
  const auto r = run_binary(kBin, "fmu export body --robots 0 -o " + (f.dir / "b.fmu").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("--robots"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(f.dir / "b.fmu"));
}

TEST(FmiCli, TheThesisInterfacesPublishedProjectRunsToCompletionWithTheEnginesColumns) {
  Folder f;
  const fs::path project = f.dir / "BIEA";
  const auto e = run_binary(kBin, "fmu export --intocps " + project.string() + " --interface thesis");
  ASSERT_EQ(e.status, 0) << e.out;
  const fs::path mm = project / "Multi-models" / "mm-new";
  const std::string csv = (f.dir / "outputs.csv").string();
  const auto r = f.cosim((mm / "mm.json").string() + " --config " + (mm / "co-sim" / "coe.json").string() + " -o " + csv +
                         " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const Json summary = Json::parse(r.out);
  EXPECT_EQ(summary["eP"], 100.0);
  EXPECT_EQ(summary["completion_step"], 20280);   // the thesis preset on the thesis's 10-cell map, 4 robots
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), 34) << header;   // the engine's 35 columns
  EXPECT_EQ(header.rfind("time,step-size,{Controller}.ControllerInstance1.onDestinationOutput,", 0), 0u) << header;
  EXPECT_TRUE(f.tmp_empty());
}

TEST(FmiCli, TheThesisInterfaceRefusesAnotherControllerOrBodyAndTheThesisControllerTheEpochHandshake) {
  Folder f;
  const auto a = run_binary(kBin, "fmu export controller --interface thesis --controller swarmcheck -o " +
                                      (f.dir / "c.fmu").string());
  EXPECT_EQ(a.status, 2);
  EXPECT_NE(a.out.find("--controller"), std::string::npos) << a.out;
  const auto b = run_binary(kBin, "fmu export --intocps " + (f.dir / "e").string() + " --preset thesis --handshake epoch");
  EXPECT_EQ(b.status, 2);
  EXPECT_NE(b.out.find("flag handshake only"), std::string::npos) << b.out;
  EXPECT_FALSE(fs::exists(f.dir / "c.fmu"));
  EXPECT_FALSE(fs::exists(f.dir / "e" / "multimodel.json"));
}

TEST(FmiCli, TheCommittedThesisMultiModelIsWhatExportWrites) {
  Folder f;   // exported the default scenario into mm/
  const std::string committed = std::string(SWARMCHECK_SOURCE_DIR) + "/scenarios/thesis/intocps/";
  for (const char* file : {"multimodel.json", "coe.json"}) {
    std::ifstream a(committed + file), b(f.dir / "mm" / file);
    const std::string x{std::istreambuf_iterator<char>(a), {}}, y{std::istreambuf_iterator<char>(b), {}};
    EXPECT_FALSE(x.empty()) << file;
    EXPECT_EQ(x, y) << file << " differs: run `swarmcheck fmu export --intocps scenarios/thesis/intocps`";
  }
}
