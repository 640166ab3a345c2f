#pragma once
// One FMU as the master loads it: the archive unpacked into a private temporary folder (removed
// when this object goes), its modelDescription.xml read (libxml2), and its shared library opened
// (dlopen, RTLD_LOCAL) with every fmi2 function the master calls resolved. Any problem is an
// InputError naming the FMU file and what was expected.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fmi/fmi2/fmi2_api.h"

namespace swarmcheck::fmi::master {

enum class VarType { real, integer, boolean, string };
const char* to_string(VarType t);

struct ModelVariable {
  std::string name;
  uint32_t value_reference = 0;
  VarType type = VarType::real;
  std::string causality;     // parameter, calculatedParameter, input, output, local, independent
  std::string variability;   // constant, fixed, tunable, discrete, continuous
};

struct ModelDescription {
  std::string fmi_version, model_name, guid, model_identifier;
  bool can_get_and_set_state = false;
  std::vector<ModelVariable> variables;
  std::map<std::string, std::size_t> by_name;   // name -> index in variables
  const ModelVariable* find(const std::string& name) const;
};

// Reads a modelDescription.xml's text (`file` names it in messages).
ModelDescription read_model_description(const std::string& xml, const std::string& file);

struct Fmi2Functions {
  fmi2InstantiateTYPE* instantiate = nullptr;
  fmi2FreeInstanceTYPE* free_instance = nullptr;
  fmi2SetupExperimentTYPE* setup_experiment = nullptr;
  fmi2EnterInitializationModeTYPE* enter_initialization_mode = nullptr;
  fmi2ExitInitializationModeTYPE* exit_initialization_mode = nullptr;
  fmi2TerminateTYPE* terminate = nullptr;
  fmi2GetRealTYPE* get_real = nullptr;
  fmi2GetIntegerTYPE* get_integer = nullptr;
  fmi2GetBooleanTYPE* get_boolean = nullptr;
  fmi2GetStringTYPE* get_string = nullptr;
  fmi2SetRealTYPE* set_real = nullptr;
  fmi2SetIntegerTYPE* set_integer = nullptr;
  fmi2SetBooleanTYPE* set_boolean = nullptr;
  fmi2SetStringTYPE* set_string = nullptr;
  fmi2DoStepTYPE* do_step = nullptr;
  fmi2GetFMUstateTYPE* get_state = nullptr;     // optional (canGetAndSetFMUstate)
  fmi2SetFMUstateTYPE* set_state = nullptr;
  fmi2FreeFMUstateTYPE* free_state = nullptr;
  fmi2SerializedFMUstateSizeTYPE* serialized_state_size = nullptr;   // optional (canSerializeFMUstate)
  fmi2SerializeFMUstateTYPE* serialize_state = nullptr;
  fmi2DeSerializeFMUstateTYPE* deserialize_state = nullptr;
  fmi2ResetTYPE* reset = nullptr;
};

class FmuLibrary {
 public:
  // An FMU's files take a few MB (this tool's) to some hundreds (resources of others'); an
  // archive that would unpack to more than `max_unpacked_bytes` is refused.
  static constexpr std::uint64_t kMaxUnpackedBytes = std::uint64_t{1} << 30;
  explicit FmuLibrary(const std::string& fmu_path, std::uint64_t max_unpacked_bytes = kMaxUnpackedBytes);
  ~FmuLibrary();
  FmuLibrary(const FmuLibrary&) = delete;
  FmuLibrary& operator=(const FmuLibrary&) = delete;

  const std::string& path() const { return path_; }
  const ModelDescription& description() const { return description_; }
  const Fmi2Functions& api() const { return api_; }
  // file:// URI of the unpacked resources/ folder.
  const std::string& resource_uri() const { return resource_uri_; }

 private:
  std::string path_;
  std::string dir_;   // the temporary folder
  std::string resource_uri_;
  ModelDescription description_;
  void* handle_ = nullptr;
  Fmi2Functions api_;
};

}  // namespace swarmcheck::fmi::master
