#pragma once
// INTO-CPS's multi-model and co-simulation configuration, as swarmcheck's master reads them.
//   multimodel.json: {"fmus": {"{FMU}": "path.fmu", ...},
//                     "connections": {"{FMU}.instance.output": ["{FMU}.instance.input", ...], ...},
//                     "parameters": {"{FMU}.instance.variable": number, ...}}
//   coe.json:        {"startTime": 0, "endTime": 30, "algorithm": {"type": "fixed-step", "size": 0.1}}
// FMU paths are relative to the multi-model's folder. Every instance named in a connection or a
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

struct CoSimConfig {
  double start_s = 0;
  double end_s = 10;
  double step_s = 0.1;
};

// Reads coe.json; `path` empty gives the defaults above.
CoSimConfig read_config(const std::string& path);

}  // namespace swarmcheck::fmi::master
