#pragma once
// Archives of the test FMU (test_fmu/test_fmu.c, built by tests/fmi/CMakeLists.txt) for the
// master's tests: the FMU variants the thesis's project has (global state declared once per
// process, a library shipped beside the binary) written into a test's folder.
#include <zip.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace swarmcheck::testing {

struct TestFmu {
  bool once_per_process = true;   // canBeInstantiatedOnlyOncePerProcess
  bool needs_helper = false;      // the binary built against libswarmcheck_test_helper.so
  bool ships_helper = true;       // ... and the archive ships it in binaries/linux64
};

inline std::string test_fmu_description(const std::string& model_identifier, bool once_per_process) {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="test" guid="{5d3c0d2e-0000-4000-8000-000000000035}">
  <CoSimulation modelIdentifier=")" + model_identifier + R"(" canBeInstantiatedOnlyOncePerProcess=")" +
         (once_per_process ? "true" : "false") + R"(" canHandleVariableCommunicationStepSize="true"/>
  <ModelVariables>
    <ScalarVariable name="gain" valueReference="0" causality="parameter" variability="fixed" initial="exact"><Real start="2.0"/></ScalarVariable>
    <ScalarVariable name="offset" valueReference="1" causality="parameter" variability="fixed" initial="exact"><Integer start="3"/></ScalarVariable>
    <ScalarVariable name="u" valueReference="2" causality="input" variability="continuous"><Real start="0.25"/></ScalarVariable>
    <ScalarVariable name="y" valueReference="3" causality="output" variability="continuous"><Real/></ScalarVariable>
    <ScalarVariable name="flagIn" valueReference="4" causality="input" variability="continuous"><Real start="1"/></ScalarVariable>
    <ScalarVariable name="flagOut" valueReference="5" causality="output" variability="continuous"><Real/></ScalarVariable>
    <ScalarVariable name="blockAtStep" valueReference="6" causality="parameter" variability="fixed" initial="exact"><Integer start="-1"/></ScalarVariable>
    <ScalarVariable name="blockSignals" valueReference="7" causality="parameter" variability="fixed" initial="exact"><Integer start="0"/></ScalarVariable>
    <ScalarVariable name="instancesInLibrary" valueReference="8" causality="output" variability="discrete"><Integer/></ScalarVariable>
    <ScalarVariable name="steps" valueReference="9" causality="local" variability="discrete"><Integer/></ScalarVariable>
    <ScalarVariable name="tag" valueReference="10" causality="parameter" variability="fixed" initial="exact"><String start="start"/></ScalarVariable>
    <ScalarVariable name="tagLength" valueReference="11" causality="output" variability="discrete"><Integer/></ScalarVariable>
  </ModelVariables>
  <ModelStructure><Outputs><Unknown index="4"/><Unknown index="6"/><Unknown index="9"/><Unknown index="12"/></Outputs></ModelStructure>
</fmiModelDescription>
)";
}

inline std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Writes `entries` (name, bytes) as the zip archive `path`.
inline void write_zip(const std::filesystem::path& path, const std::vector<std::pair<std::string, std::string>>& entries) {
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (!z) throw std::runtime_error("cannot create " + path.string());
  for (const auto& [name, bytes] : entries) {
    zip_source_t* s = zip_source_buffer(z, bytes.data(), bytes.size(), 0);
    if (!s || zip_file_add(z, name.c_str(), s, ZIP_FL_OVERWRITE) < 0) throw std::runtime_error("cannot add " + name);
  }
  if (zip_close(z) != 0) throw std::runtime_error("cannot write " + path.string());
}

// The test FMU as `dir`/`name`; returns its path.
inline std::string write_test_fmu(const std::filesystem::path& dir, const std::string& name, const TestFmu& f = {}) {
  const std::string id = f.needs_helper ? "swarmcheck_test_fmu_bundled" : "swarmcheck_test_fmu";
  std::vector<std::pair<std::string, std::string>> entries{
      {"modelDescription.xml", test_fmu_description(id, f.once_per_process)},
      {"binaries/linux64/" + id + ".so", file_bytes(f.needs_helper ? SWARMCHECK_TEST_FMU_BUNDLED_SO : SWARMCHECK_TEST_FMU_SO)}};
  if (f.needs_helper && f.ships_helper)
    entries.emplace_back("binaries/linux64/libswarmcheck_test_helper.so", file_bytes(SWARMCHECK_TEST_HELPER_SO));
  const std::filesystem::path path = dir / name;
  write_zip(path, entries);
  return path.string();
}

}  // namespace swarmcheck::testing
