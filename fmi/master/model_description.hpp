#pragma once
// An FMU's modelDescription.xml as the master reads it (libxml2): its variables with their start
// values, and the co-simulation capabilities the master acts on. Any problem is an InputError
// naming the file (and line) and what was expected.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace swarmcheck::fmi::master {

enum class VarType { real, integer, boolean, string };
const char* to_string(VarType t);

struct ModelVariable {
  std::string name;
  uint32_t value_reference = 0;
  VarType type = VarType::real;
  std::string causality;     // parameter, calculatedParameter, input, output, local, independent
  std::string variability;   // constant, fixed, tunable, discrete, continuous
  // The start attribute, checked against the type when read: Real and Integer as `start_number`,
  // Boolean as 1 / 0 there too, String as `start_text`.
  bool has_start = false;
  double start_number = 0;
  std::string start_text;
  int line = 0;   // in modelDescription.xml, for messages
};

struct ModelDescription {
  std::string fmi_version, model_name, guid, model_identifier;
  bool can_get_and_set_state = false;
  // All of the FMU's state is the library's (global variables): one instance per loaded copy of
  // the library (the master loads a copy per instance).
  bool can_be_instantiated_only_once_per_process = false;
  std::vector<ModelVariable> variables;
  std::map<std::string, std::size_t> by_name;   // name -> index in variables
  const ModelVariable* find(const std::string& name) const;
};

// Reads a modelDescription.xml's text (`file` names it in messages).
ModelDescription read_model_description(const std::string& xml, const std::string& file);

}  // namespace swarmcheck::fmi::master
