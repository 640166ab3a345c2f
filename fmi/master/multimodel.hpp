#pragma once
// INTO-CPS's multi-model and co-simulation configuration, as swarmcheck's master reads them.
//   multimodel.json: {"fmus": {"{FMU}": "path.fmu", ...},
//                     "connections": {"{FMU}.instance.output": ["{FMU}.instance.input", ...], ...},
//                     "parameters": {"{FMU}.instance.variable": number, ...}}
//   coe.json:        {"startTime": 0, "endTime": 30, "algorithm": {"type": "fixed-step", "size": 0.1},
//                     "logVariables": {"{FMU}.instance": ["variable", ...]}, ...}
// An FMU path is relative to the multi-model's folder; a file not there is looked for where the
// INTO-CPS application keeps it, in the project's FMUs/ folder (PROJECT/Multi-models/.../mm.json
// -> PROJECT/FMUs/X.fmu), so a published project runs as it is on disk. Every instance named in a connection or a
// parameter is one instance of its FMU; instances are stepped (Gauss-Seidel) in the order of their
// FMUs in "fmus", then in the order they first appear in the file. Every problem is an InputError
// naming the file and the JSON path.
#include <cstdint>
#include <string>
#include <vector>

namespace swarmcheck::fmi::master {

struct PortName {   // "{FMU}.instance.variable"
  std::string fmu, instance, variable;
  std::string text() const { return fmu + "." + instance + "." + variable; }
};

struct Connection {
  PortName from;
  PortName to;
  std::string where;   // JSON path of the target, for messages
};

struct Parameter {
  PortName port;
  double value = 0;
  bool integral = false;   // written as an integer (or a boolean: 1 / 0)
  bool is_text = false;    // a string (for a String variable)
  std::string text;
  std::string where;
};

struct MultiModel {
  std::string file;                                     // as given
  std::vector<std::pair<std::string, std::string>> fmus;   // key, resolved path, in file order
  std::vector<std::pair<std::string, std::string>> instances;   // FMU key, instance, stepping order
  std::vector<Connection> connections;
  std::vector<Parameter> parameters;
};

MultiModel read_multimodel(const std::string& path);

// A variable the configuration asks to log ("logVariables": {"{FMU}.instance": ["var", ...]}).
struct LogVariable {
  PortName port;
  std::string where;   // "file: logVariables.{FMU}.instance[k]", for messages
};

struct CoSimConfig {
  double start_s = 0;
  double end_s = 10;
  double step_s = 0.1;
  std::vector<LogVariable> log_variables;
};

// Reads coe.json; `path` empty gives the defaults above. Every key the INTO-CPS engine writes in a
// configuration (coe.json, and a run folder's config-simulation.json) is accepted; those that
// change nothing the master computes (live graphs, logging, real-time pacing, ...) are ignored;
// stabalizationEnabled true (iterated steps) is refused, as is any other key.
CoSimConfig read_config(const std::string& path);

}  // namespace swarmcheck::fmi::master
