#pragma once
// `swarmcheck fmu export`: FMI 2.0 co-simulation FMUs (zip archives) of the Environment, the
// Controller and the Body, and the thesis's architecture as an INTO-CPS multi-model.
//   X.fmu = modelDescription.xml
//           binaries/linux64/swarmcheck_<kind>.so   the fmi2 library (built into swarmcheck)
//           resources/swarmcheck-fmu.json            kind, robot and obstacle counts, scenario
// Archives are byte-identical for the same request (fixed timestamps, fixed order).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fmi/fmu/component.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::fmi {

// The scenario with n robots: its own when it has n, otherwise n robots spread over its free
// cells in raster order (cell floor(k F / n) of the F free cells, k = 0..n-1), at cell centres.
// InputError when n < 1 or n > F.
exploration::Scenario scenario_with_robots(const exploration::Scenario& s, int32_t n);

// The scenario whose values the thesis interface's Environment takes as start values by default:
// the thesis Environment FMU's own (its modelDescription.xml: 4 robots at the corners of a
// 10-cell map, ertu_perc 0.002, ...), rule set thesis; of its 10 obstacle cells the last two
// (both cell (0, 0), under robot 1) are left out, so 8 take part and the FMU has 10 slots.
exploration::Scenario thesis_interface_scenario();

// The setup of an FMU of `kind` for scenario s (the Environment's robots and obstacles are s's;
// the thesis interface's Environment has at least the thesis's 10 obstacle slots).
FmuSetup fmu_setup(Kind kind, const exploration::Scenario& s, Interface interface = Interface::swarmcheck);

// The bytes of the .fmu archive.
std::string fmu_archive(const FmuSetup& setup);
// The same with another build of the FMUs' library (tests: a library with a fault built in).
std::string fmu_archive(const FmuSetup& setup, const std::string& library);

// Writes the archive to `path` atomically.
void write_fmu(const FmuSetup& setup, const std::string& path);

enum class Handshake { flag, epoch };

// The FMU files a multi-model names (as written in it: relative to it, or absolute). The thesis
// layout's bodies are one file per robot (`bodies`, else `body` for every robot).
struct ModelFmus {
  std::string environment, controller, body;
  std::vector<std::string> bodies = {};
};

// The thesis's architecture for scenario s as an INTO-CPS multi-model (JSON text): one
// Environment, one Controller and one Body instance per robot, connected as the thesis's FMUs are,
// with the scenario's start positions and handshake as parameters (swarmcheck's interface).
// every_parameter: also every parameter the scenario decides (the Environment's, every gain and
// body parameter), so that FMUs of any start values run s (conform --fmu's cases).
std::string intocps_multimodel(const exploration::Scenario& s, Handshake handshake, const ModelFmus& files,
                               bool every_parameter = false);
// The same in the thesis interface, laid out as thesis A's published mm.json (write_intocps_thesis).
std::string thesis_multimodel(const exploration::Scenario& s, const ModelFmus& files, bool every_parameter = false);
// An INTO-CPS configuration: fixed step step_s from 0 to end_s.
std::string intocps_config(double step_s, double end_s);

// The thesis's architecture in `dir` (created if missing): Environment.fmu, Controller.fmu,
// Body.fmu, multimodel.json (one Environment, one Controller and one Body instance per robot,
// connected as the thesis's FMUs are) and coe.json (fixed step = step_size; end time = the
// scenario's completion time as the library computes it, or max_steps when it does not complete;
// or end_time_s when given, without that run).
void write_intocps(const exploration::Scenario& s, Handshake handshake, const std::string& dir,
                   std::optional<double> end_time_s = std::nullopt);

// Thesis A's published INTO-CPS project laid out in `dir` with swarmcheck's FMUs in place of the
// thesis's (`fmu export --intocps DIR --interface thesis`): FMUs/Environment.fmu, UController.fmu,
// Body_Block1..N.fmu (thesis interface: the thesis controller and the intocps body);
// Multi-models/mm-new/mm.json with the published FMU keys, instance names, connections and
// parameters; Multi-models/mm-new/co-sim/coe.json with the published configuration's keys. The
// end as write_intocps's.
struct ThesisProject {
  std::string multimodel, config;   // the paths written
};
ThesisProject write_intocps_thesis(const exploration::Scenario& s, const std::string& dir,
                                   std::optional<double> end_time_s = std::nullopt);

}  // namespace swarmcheck::fmi
