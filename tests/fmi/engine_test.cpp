// The master does what the INTO-CPS engine does, shown on the test FMU (test_fmu/test_fmu.c),
// which behaves as the thesis's FMUs: start values written before initialisation (the FMU does
// not apply its own), a copy of the library per instance for a global-state FMU, libraries
// shipped beside the binary found, time by repeated addition, outputs.csv in the engine's format,
// and every key of the engine's configurations accepted.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fmi/master/master.hpp"
#include "fmi/master/outputs_csv.hpp"
#include "spec/util/input_error.hpp"
#include "tests/fmi/scratch.hpp"
#include "tests/fmi/test_fmu.hpp"

namespace {

namespace fs = std::filesystem;
namespace fm = swarmcheck::fmi::master;
using Json = nlohmann::ordered_json;
using swarmcheck::testing::TestFmu;
using swarmcheck::testing::write_test_fmu;

struct Folder {
  fs::path dir = swarmcheck::testing::fmi_scratch("engine");
  ~Folder() { fs::remove_all(dir); }
  std::string write(const Json& j, const std::string& name) const {
    std::ofstream(dir / name) << j.dump(2);
    return (dir / name).string();
  }
};

fm::CoSimConfig steps(int n) {
  fm::CoSimConfig c;
  c.end_s = 0.1 * n;
  return c;
}

}  // namespace

TEST(FmiEngine, StartValuesOfEveryParameterAndInputAreWrittenBeforeInitialisationTheMultiModelsWinning) {
  Folder f;
  write_test_fmu(f.dir, "a.fmu");
  write_test_fmu(f.dir, "b.fmu");
  Json mm;
  mm["fmus"] = {{"{A}", "a.fmu"}, {"{B}", "b.fmu"}};
  mm["parameters"] = {{"{A}.a.blockAtStep", -1}, {"{B}.b.gain", 4.5}, {"{B}.b.offset", -1}, {"{B}.b.u", 0.5},
                      {"{B}.b.tag", "from the multi-model"}};
  fm::Master m(fm::read_multimodel(f.write(mm, "mm.json")), steps(2), fm::Algorithm::jacobi);
  const auto real = [&](const std::string& name) { return m.value(m.port(name)); };
  // The description's start values (the FMU's own init would leave 0.2f, 123.0, 0, "init").
  EXPECT_EQ(real("{A}.a.gain"), 2.0);
  EXPECT_EQ(real("{A}.a.u"), 0.25);
  EXPECT_EQ(real("{A}.a.offset"), 3);
  EXPECT_EQ(real("{A}.a.flagIn"), 1.0);
  EXPECT_EQ(m.text(m.port("{A}.a.tag")), "start");
  EXPECT_EQ(real("{A}.a.tagLength"), 5);   // the FMU read it at initialisation: written before
  // The multi-model's parameters instead, inputs included.
  EXPECT_EQ(real("{B}.b.gain"), 4.5);
  EXPECT_EQ(real("{B}.b.offset"), -1);
  EXPECT_EQ(real("{B}.b.u"), 0.5);
  EXPECT_EQ(real("{B}.b.tagLength"), 20);
  while (!m.done()) m.step();
  EXPECT_EQ(real("{A}.a.y"), 2 * (2.0 * 0.25 + 3));
  EXPECT_EQ(real("{B}.b.y"), 2 * (4.5 * 0.5 - 1));
}

TEST(FmiEngine, AGlobalStateFmuDeclaredOncePerProcessGetsALibraryCopyPerInstanceAndOnlyThen) {
  Folder f;
  for (const bool once : {true, false}) {
    const std::string file = once ? "once.fmu" : "shared.fmu";
    write_test_fmu(f.dir, file, TestFmu{once, false, true});
    Json mm;
    mm["fmus"] = {{"{T}", file}};
    mm["parameters"] = {{"{T}.t1.gain", 1.0}, {"{T}.t2.gain", 2.0}, {"{T}.t3.gain", 3.0}};
    fm::Master m(fm::read_multimodel(f.write(mm, "mm.json")), steps(4), fm::Algorithm::jacobi);
    while (!m.done()) m.step();
    for (int k = 1; k <= 3; ++k) {
      const std::string t = "{T}.t" + std::to_string(k) + ".";
      if (once) {
        EXPECT_EQ(m.value(m.port(t + "instancesInLibrary")), 1) << t;
        EXPECT_EQ(m.value(m.port(t + "y")), 4 * (k * 0.25 + 3)) << t;   // each its own model
        EXPECT_EQ(m.value(m.port(t + "steps")), 4) << t;
      } else {
        // One library for the three: one model, instantiated three times and stepped 12 times.
        EXPECT_EQ(m.value(m.port(t + "instancesInLibrary")), 3) << t;
        EXPECT_EQ(m.value(m.port(t + "steps")), 12) << t;
      }
    }
  }
}

TEST(FmiEngine, ALibraryAnFmuShipsBesideItsBinaryIsFoundAndItsAbsenceIsNamed) {
  Folder f;
  write_test_fmu(f.dir, "ships.fmu", TestFmu{true, true, true});
  write_test_fmu(f.dir, "lacks.fmu", TestFmu{true, true, false});
  Json mm;
  mm["fmus"] = {{"{S}", "ships.fmu"}};
  mm["parameters"] = {{"{S}.s1.gain", 1.0}, {"{S}.s2.gain", 8.0}};   // two copies, one shipped library
  {
    fm::Master m(fm::read_multimodel(f.write(mm, "ships.json")), steps(1), fm::Algorithm::jacobi);
    m.step();
    EXPECT_EQ(m.value(m.port("{S}.s1.y")), 1.0 * 0.25 + 3);
    EXPECT_EQ(m.value(m.port("{S}.s2.y")), 8.0 * 0.25 + 3);
  }
  mm["fmus"] = {{"{S}", "lacks.fmu"}};
  try {
    fm::Master m(fm::read_multimodel(f.write(mm, "lacks.json")), steps(1), fm::Algorithm::jacobi);
    FAIL() << "an FMU whose library needs a library it does not ship loaded";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lacks.fmu: cannot load its library"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("libswarmcheck_test_helper.so"), std::string::npos) << e.what();
  }
}

TEST(FmiEngine, TimeAdvancesByRepeatedAdditionAndStepsEndAsTheEnginesDo) {
  Folder f;
  write_test_fmu(f.dir, "a.fmu");
  Json mm;
  mm["fmus"] = {{"{A}", "a.fmu"}};
  mm["parameters"] = {{"{A}.a.gain", 1.0}};
  fm::CoSimConfig c;
  c.end_s = 1000;
  fm::Master m(fm::read_multimodel(f.write(mm, "mm.json")), c, fm::Algorithm::jacobi);
  double t = 0;
  int64_t n = 0;
  for (; t + 0.1 <= 1000; t += 0.1) ++n;
  // The sum of 9999 steps of 0.1 is 999.9000000001588: one more would pass endTime, so the engine
  // stops one step short of the 10^4 that k h would give.
  EXPECT_EQ(n, 9999);
  EXPECT_EQ(m.total_steps(), n);
  while (!m.done()) m.step();
  EXPECT_EQ(m.steps(), n);
  EXPECT_EQ(m.time_s(), t);                               // the same additions, the same bits
  EXPECT_NE(m.time_s(), static_cast<double>(n) * 0.1);   // not k h: the engine's drift
  EXPECT_LT(std::fabs(m.time_s() - static_cast<double>(n) * 0.1), 1e-9);
}

TEST(FmiEngine, OutputsCsvHasTheEnginesColumnsSortedAndItsNumbers) {
  Folder f;
  write_test_fmu(f.dir, "t.fmu");
  Json mm;
  mm["fmus"] = {{"{Source}", "t.fmu"}, {"{Sink}", "t.fmu"}};
  mm["connections"] = {{"{Source}.src.y", {"{Sink}.sink.u"}}, {"{Source}.src.flagOut", {"{Sink}.sink.flagIn"}}};
  mm["parameters"] = {{"{Source}.src.u", 0.1}};
  // endTime 0.35: steps at 0, 0.1, 0.2 (0.30000000000000004 + 0.1 > 0.35).
  Json coe = {{"startTime", 0}, {"endTime", 0.35}, {"algorithm", {{"type", "fixed-step"}, {"size", 0.1}}},
              {"logVariables", {{"{Sink}.sink", {"steps", "y", "flagOut"}}, {"{Source}.src", {"y"}}}}};
  fm::Master m(fm::read_multimodel(f.write(mm, "mm.json")), fm::read_config(f.write(coe, "coe.json")),
               fm::Algorithm::jacobi);
  const fm::OutputsCsv csv(m);
  std::ostringstream out;
  csv.header(out);
  csv.row(out, m.time_s(), 0.0);
  while (!m.done()) {
    m.step();
    csv.row(out, m.time_s(), m.step_size_s());
  }
  // Connected outputs and logged variables, once each ({Source}.src.y is both), by name.
  std::istringstream lines(out.str());
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "time,step-size,{Sink}.sink.flagOut,{Sink}.sink.steps,{Sink}.sink.y,{Source}.src.flagOut,{Source}.src.y");
  std::getline(lines, line);
  EXPECT_EQ(line, "0.0,0.0,0.0,0,0.0,0.0,0.0");   // after initialisation
  std::getline(lines, line);
  // Step 1: the sink read the source's outputs as of t = 0 (Jacobi): y 0, flag 0; the source's
  // unconnected flagIn has its start value, 1.
  EXPECT_EQ(line, "0.1,0.1,0.0,1,3.0,1.0,3.2");
  std::getline(lines, line);
  EXPECT_EQ(line, "0.2,0.1,1.0,2,12.4,1.0,6.4");   // sink: 3 + (2 * 3.2 + 3)
  std::getline(lines, line);
  EXPECT_EQ(line.substr(0, 24), "0.30000000000000004,0.1,");
  EXPECT_FALSE(std::getline(lines, line));
}

TEST(FmiEngine, NumbersAreWrittenAsJavasDoubleToString) {
  const std::vector<std::pair<double, std::string>> cases{
      {0.0, "0.0"}, {-0.0, "-0.0"}, {1.0, "1.0"}, {-1.0, "-1.0"}, {0.1, "0.1"}, {0.30000000000000004, "0.30000000000000004"},
      {100.0, "100.0"}, {9.50469855566091, "9.50469855566091"}, {0.001, "0.001"}, {0.00099, "9.9E-4"},
      {1e-5, "1.0E-5"}, {9999999.0, "9999999.0"}, {1e7, "1.0E7"}, {123456789.0, "1.23456789E8"}, {1e21, "1.0E21"},
      {2e23, "2.0E23"}, {4.9e-324, "4.9E-324"}, {1.7976931348623157e308, "1.7976931348623157E308"},
      {-0.2552543962467425, "-0.2552543962467425"}, {0.0494845493238586, "0.0494845493238586"},
      {std::numeric_limits<double>::quiet_NaN(), "NaN"}, {std::numeric_limits<double>::infinity(), "Infinity"},
      {-std::numeric_limits<double>::infinity(), "-Infinity"}};
  for (const auto& [v, text] : cases) EXPECT_EQ(fm::java_double_text(v), text) << text;
}

TEST(FmiEngine, EveryKeyOfTheEnginesConfigurationsIsAcceptedAndOthersAreRefused) {
  Folder f;
  // coe.json and config-simulation.json as the INTO-CPS application writes them (thesis A's project).
  const Json coe = Json::parse(R"({"startTime":0,"endTime":3600,"multimodel_path":"Multi-models/mm-new/mm.json",
    "liveGraphColumns":1,"liveGraphVisibleRowCount":1,"graphs":[],"livestreamInterval":0,"logVariables":{},
    "visible":false,"loggingOn":false,"overrideLogLevel":null,"enableAllLogCategoriesPerInstance":false,
    "algorithm":{"type":"fixed-step","size":0.1},"postProcessingScript":"","multimodel_crc":"1dcd914a9a969aa82c6f97e08c9372c8",
    "parallelSimulation":false,"stabalizationEnabled":false,"global_absolute_tolerance":0,
    "global_relative_tolerance":0.01,"simulationProgramDelay":true})");
  const fm::CoSimConfig c = fm::read_config(f.write(coe, "coe.json"));
  EXPECT_EQ(c.end_s, 3600);
  EXPECT_EQ(c.step_s, 0.1);
  EXPECT_TRUE(c.log_variables.empty());
  const Json simulation = Json::parse(R"({"startTime":0,"endTime":3600,"reportProgress":true,"liveLogInterval":0,"logLevels":{}})");
  EXPECT_EQ(fm::read_config(f.write(simulation, "config-simulation.json")).end_s, 3600);
  const auto refused = [&](Json j, const std::string& expected) {
    try {
      fm::read_config(f.write(j, "bad.json"));
      ADD_FAILURE() << "accepted: " << j.dump();
    } catch (const swarmcheck::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  Json j = coe;
  j["stepSize"] = 0.1;
  refused(j, "bad.json: stepSize: unknown key: expected one of the INTO-CPS engine's (startTime, endTime,");
  j = coe;
  j["logvariables"] = Json::object();
  refused(j, "logvariables: unknown key: did you mean \"logVariables\"?");
  j = coe;
  j["stabalizationEnabled"] = true;
  refused(j, "stabalizationEnabled: expected false");
  j = coe;
  j["logVariables"] = {{"{A}.a", "y"}};
  refused(j, "logVariables.{A}.a: expected a list of variable names");
  // A logged variable the FMU does not record as an output or a local.
  write_test_fmu(f.dir, "a.fmu");
  Json mm;
  mm["fmus"] = {{"{A}", "a.fmu"}};
  mm["parameters"] = {{"{A}.a.gain", 1.0}};
  j = coe;
  j["logVariables"] = {{"{A}.a", {"y", "gain"}}};
  try {
    fm::Master m(fm::read_multimodel(f.write(mm, "mm.json")), fm::read_config(f.write(j, "log.json")), fm::Algorithm::jacobi);
    ADD_FAILURE() << "a parameter logged";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("log.json: logVariables.{A}.a[1]: gain is parameter: the engine logs outputs and locals only"),
              std::string::npos) << e.what();
  }
}

TEST(FmiEngine, FmusOfAPublishedProjectAreFoundInItsFmusFolder) {
  Folder f;
  fs::create_directories(f.dir / "project" / "FMUs");
  fs::create_directories(f.dir / "project" / "Multi-models" / "mm-new" / "co-sim" / "R_1");
  write_test_fmu(f.dir / "project" / "FMUs", "Test.fmu");
  Json mm;
  mm["fmus"] = {{"{A}", "Test.fmu"}};
  mm["parameters"] = {{"{A}.a.gain", 1.0}};
  for (const fs::path& folder : {f.dir / "project" / "Multi-models" / "mm-new", f.dir / "project" / "Multi-models" / "mm-new" / "co-sim" / "R_1"}) {
    std::ofstream(folder / "mm.json") << mm.dump();
    const fm::MultiModel read = fm::read_multimodel((folder / "mm.json").string());
    EXPECT_EQ(fs::canonical(read.fmus[0].second), fs::canonical(f.dir / "project" / "FMUs" / "Test.fmu"));
  }
}
