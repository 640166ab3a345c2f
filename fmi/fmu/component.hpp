#pragma once
// One FMU instance's model behind the fmi2 API (fmi2_entry.cpp): its variables (bound port
// structs, variable_table.hpp), initialisation from its parameters, a step, and its whole state
// as bytes (fmi2GetFMUstate / SetFMUstate / Serialize). The three kinds wrap the library:
//   Environment: impl's Environment (spec/exploration/environment_step.hpp) with the thesis's
//                flag handshake or the epoch handshake (spec/exploration/handshake.hpp)
//   Controller:  spec controller_step (and its locals), one robot
//   Body:        spec body_step, one robot
// Every failure is an FmuError with a message for the master's logger; nothing aborts.
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "fmi/fmu/variable_table.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::fmi {

enum class Kind { environment, controller, body };
const char* to_string(Kind k);                 // "environment", ...
std::string model_identifier(Kind k);          // "swarmcheck_environment", ...
std::string model_name(Kind k);                // "swarmcheck Environment", ...

// Whose variables an FMU has: swarmcheck's (ports.hpp), or those of thesis A's published FMUs
// (thesis_ports.hpp), so that they replace the thesis's own in its multi-model.
enum class Interface { swarmcheck, thesis };
const char* to_string(Interface i);            // "swarmcheck", "thesis"

class FmuError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What an FMU is, fixed at export (resources/swarmcheck-fmu.json): its kind, the robot and
// obstacle counts, and the scenario whose values are the parameters' start values.
struct FmuSetup {
  Kind kind = Kind::environment;
  Interface interface = Interface::swarmcheck;
  int32_t robots = 0;      // Environment only
  int32_t obstacles = 0;   // Environment only: the scenario's, or more slots (thesis interface)
  exploration::Scenario scenario;
};

// The model name of an FMU of this setup ("swarmcheck Environment", "swarmcheck Environment
// (thesis interface)", ...).
std::string model_name(const FmuSetup& s);

// The setup as the resources file's JSON, and back (FmuError on anything unexpected).
std::string setup_to_json(const FmuSetup& s);
FmuSetup setup_from_json(const std::string& text);

class Component {
 public:
  virtual ~Component() = default;
  const VariableTable& table() const { return table_; }
  // fmi2ExitInitializationMode: build the model from the parameters (FmuError if they are bad).
  virtual void initialize() = 0;
  // fmi2DoStep from the communication point t over h seconds (FmuError if the step cannot be taken).
  virtual void step(double t_s, double h_s) = 0;
  // fmi2SetupExperiment's start time (before initialize()).
  virtual void start_at(double /*t_s*/) {}
  // The start values of every variable (fmi2Instantiate, fmi2Reset).
  virtual void defaults() = 0;
  // Brings variables computed only when read up to date (before any fmi2Get and state save).
  virtual void settle() {}

  // The whole state: every variable's value, then what the kind keeps besides.
  std::vector<uint8_t> save() const;
  void restore(std::span<const uint8_t> bytes);   // FmuError if the bytes are not this FMU's

 protected:
  // `kind`: whose variable descriptions its table gives ("environment", "controller", "body").
  explicit Component(std::string_view kind) : table_(kind) {}
  virtual void save_extra(std::vector<uint8_t>& /*out*/) const {}
  // Reads what save_extra wrote from `in` (advancing it); FmuError if malformed.
  virtual void restore_extra(std::span<const uint8_t>& /*in*/) {}
  VariableTable table_;
};

std::unique_ptr<Component> make_component(const FmuSetup& setup);

// The GUID of an FMU: a digest of its setup and its variables (the same for the same export).
std::string fmu_guid(const FmuSetup& setup);

}  // namespace swarmcheck::fmi
