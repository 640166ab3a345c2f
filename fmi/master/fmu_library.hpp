#pragma once
// One FMU as the master loads it: the archive unpacked into a private temporary folder (removed
// when this object goes), its modelDescription.xml read (model_description.hpp), and its shared
// library opened (dlopen, RTLD_LOCAL) with every fmi2 function the master calls resolved.
//   - Libraries the FMU ships beside its binary (binaries/linux64/*.so*, e.g. a libwebsockets the
//     model needs) are loaded first, so the model's library finds them by their soname.
//   - A model whose state is global (canBeInstantiatedOnlyOncePerProcess) gets one copy of its
//     library per instance: load_copy() copies the .so under a new name and dlopens it, and the
//     dynamic loader, which shares a library by file identity, gives the copy its own globals.
//     (The shipped libraries above are loaded once and shared by the copies.)
// Any problem is an InputError naming the FMU file and what was expected.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fmi/fmi2/fmi2_api.h"
#include "fmi/master/model_description.hpp"

namespace swarmcheck::fmi::master {

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
  const std::string& folder() const { return dir_; }   // the temporary folder it is unpacked in
  const ModelDescription& description() const { return description_; }
  // The functions of a loaded copy of the library (0: the one loaded by the constructor).
  // (The reference stays valid while this object lives: copies loaded later do not move it.)
  const Fmi2Functions& api(std::size_t copy = 0) const { return copies_[copy]->api; }
  std::size_t copies() const { return copies_.size(); }
  // Loads one more copy of the model's library (see the header comment); returns its number.
  std::size_t load_copy();
  // The library is not unloaded when this object goes (its folder is still removed): for an FMU
  // a call of which never returned, whose code may still run (a thread it started).
  void keep_loaded() { keep_loaded_ = true; }
  // file:// URI of the unpacked resources/ folder.
  const std::string& resource_uri() const { return resource_uri_; }

 private:
  struct Copy {
    void* handle = nullptr;
    Fmi2Functions api;
  };
  Copy load(const std::string& so) const;
  void unload();

  std::string path_;
  std::string dir_;   // the temporary folder
  int temp_slot_ = -1;   // its registration with impl/io/interrupt.hpp (removed if a signal ends the process)
  std::string so_;    // the model's library in it
  std::string resource_uri_;
  ModelDescription description_;
  std::vector<void*> shipped_;   // the libraries shipped beside the model's, in load order
  std::vector<std::unique_ptr<Copy>> copies_;
  bool keep_loaded_ = false;
};

}  // namespace swarmcheck::fmi::master
