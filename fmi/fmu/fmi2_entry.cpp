// The fmi2 functions the FMU's shared library exports (the only symbols it exports: fmu.map).
// Each call checks the instance's phase as the FMI 2.0 state machine allows (section 4.2.4),
// turns every failure into fmi2Error with a message through the master's logger, and never lets
// an exception or an abort out.
#include <cstdarg>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "fmi/fmi2/fmi2_api.h"
#include "fmi/fmu/component.hpp"

#define FMI2_EXPORT extern "C" __attribute__((visibility("default")))

namespace swarmcheck::fmi {
namespace {

enum class Phase { instantiated, initialization, stepping, terminated, failed };

struct Instance {
  // First what every fmi2Get/Set/DoStep reads, on one cache line: a master calls hundreds of
  // instances per step, so each call's chain of dependent loads is what it costs.
  Phase phase = Phase::instantiated;
  uint32_t slot_count = 0;
  const VariableTable::Slot* slots = nullptr;   // component->table()'s, which never move
  std::unique_ptr<Component> component;
  double time_s = 0;
  bool logging = false;
  fmi2CallbackLogger logger = nullptr;
  fmi2ComponentEnvironment environment = nullptr;
  std::string name;
};

struct SavedState {
  std::vector<uint8_t> bytes;
  Phase phase;
  double time_s;
};

void log(const Instance* in, fmi2Status status, const char* category, const std::string& message) {
  if (!in || !in->logger) return;
  if (status == fmi2OK && !in->logging) return;
  std::string escaped;   // the logger takes a printf format: a '%' in a message is literal
  for (const char c : message) {
    escaped += c;
    if (c == '%') escaped += '%';
  }
  in->logger(in->environment, in->name.c_str(), status, category, escaped.c_str());
}

fmi2Status fail(Instance* in, const std::string& message) {
  log(in, fmi2Error, "logError", message);
  return fmi2Error;
}

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::instantiated: return "instantiated";
    case Phase::initialization: return "initialization mode";
    case Phase::stepping: return "step mode";
    case Phase::terminated: return "terminated";
    case Phase::failed: return "error";
  }
  return "?";
}

[[gnu::noinline, gnu::cold]] fmi2Status wrong_phase(Instance* in, const char* what) {
  return fail(in, std::string(what) + ": not allowed in " + phase_name(in->phase));
}

// Called from a catch handler: turns the exception being handled into fmi2Error and a message.
[[gnu::noinline, gnu::cold]] fmi2Status exception_status(Instance* in, const char* what) {
  try {
    throw;
  } catch (const FmuError& e) {
    return fail(in, std::string(what) + ": " + e.what());
  } catch (const std::bad_alloc&) {
    in->phase = Phase::failed;
    return fail(in, std::string(what) + ": out of memory");
  } catch (const std::exception& e) {
    in->phase = Phase::failed;
    return fail(in, std::string(what) + ": internal error (please report): " + e.what());
  } catch (...) {
    in->phase = Phase::failed;
    return fail(in, std::string(what) + ": internal error (please report)");
  }
}

// Runs `body` for a valid instance in one of the allowed phases.
template <class Body>
fmi2Status guarded(fmi2Component c, const char* what, std::initializer_list<Phase> allowed, Body&& body) {
  auto* in = static_cast<Instance*>(c);
  if (!in) return fmi2Error;
  bool ok = false;
  for (const Phase p : allowed) ok = ok || p == in->phase;
  if (!ok) return wrong_phase(in, what);
  try {
    return body(*in);
  } catch (...) {
    return exception_status(in, what);
  }
}

// file:///a/b%20c/ -> /a/b c/
std::string path_of_uri(const std::string& uri) {
  std::string rest;
  if (uri.rfind("file:///", 0) == 0) rest = uri.substr(7);
  else if (uri.rfind("file://localhost/", 0) == 0) rest = uri.substr(16);
  else if (uri.rfind("file:/", 0) == 0) rest = uri.substr(5);
  else throw FmuError("fmuResourceLocation: expected a file: URI, got '" + uri + "'");
  std::string out;
  for (std::size_t k = 0; k < rest.size(); ++k) {
    if (rest[k] == '%' && k + 2 < rest.size()) {
      out += static_cast<char>(std::stoi(rest.substr(k + 1, 2), nullptr, 16));
      k += 2;
    } else {
      out += rest[k];
    }
  }
  if (!out.empty() && out.back() != '/') out += '/';
  return out;
}

// The messages are built out of line: the checks below run for every value of every call.
[[gnu::noinline, gnu::cold]] void no_such_variable(const Instance& in, fmi2ValueReference vr, const char* what) {
  const Variable* v = in.component->table().find(vr);
  if (!v) throw FmuError(std::string(what) + ": no variable has value reference " + std::to_string(vr));
  throw FmuError(std::string(what) + ": " + v->name + " (value reference " + std::to_string(vr) + ") is " +
                 to_string(v->type));
}

[[gnu::noinline, gnu::cold]] void not_settable(const Instance& in, fmi2ValueReference vr, const char* what) {
  const Variable& v = *in.component->table().find(vr);
  throw FmuError(std::string(what) + ": " + v.name + " (" + to_string(v.causality) + ", " + to_string(v.variability) +
                 ") cannot be set in " + phase_name(in.phase));
}

inline const VariableTable::Slot& variable(const Instance& in, fmi2ValueReference vr, BaseType type, const char* what) {
  if (vr >= in.slot_count || in.slots[vr].type != type) [[unlikely]]
    no_such_variable(in, vr, what);
  return in.slots[vr];
}

// Whether variable vr may be set now (FMI 2.0 section 4.2.4, table of fmi2SetXXX).
inline void check_settable(const Instance& in, const VariableTable::Slot& s, fmi2ValueReference vr, const char* what) {
  if (s.causality == Causality::input) return;
  const bool before_init = in.phase == Phase::instantiated || in.phase == Phase::initialization;
  if (s.causality == Causality::parameter && before_init) return;
  not_settable(in, vr, what);
}

template <class T, class Get>
fmi2Status get_values(fmi2Component c, const fmi2ValueReference vr[], size_t n, T value[], BaseType type,
                      const char* what, Get&& get) {
  return guarded(c, what, {Phase::initialization, Phase::stepping, Phase::terminated, Phase::failed}, [&](Instance& in) {
    if (n > 0 && (!vr || !value)) throw FmuError("null array");
    bool settled = false;
    for (size_t k = 0; k < n; ++k) {
      const VariableTable::Slot& s = variable(in, vr[k], type, what);
      if (s.causality == Causality::local && !settled) {   // locals may be computed when read
        in.component->settle();
        settled = true;
      }
      value[k] = get(s);
    }
    return fmi2OK;
  });
}

template <class T, class Set>
fmi2Status set_values(fmi2Component c, const fmi2ValueReference vr[], size_t n, const T value[], BaseType type,
                      const char* what, Set&& set) {
  return guarded(c, what, {Phase::instantiated, Phase::initialization, Phase::stepping}, [&](Instance& in) {
    if (n > 0 && (!vr || !value)) throw FmuError("null array");
    // Every variable is checked before any is set (a refused call changes nothing).
    constexpr size_t kOnStack = 32;
    const VariableTable::Slot* on_stack[kOnStack];
    std::vector<const VariableTable::Slot*> on_heap(n > kOnStack ? n : 0);
    const VariableTable::Slot** slots = n > kOnStack ? on_heap.data() : on_stack;
    for (size_t k = 0; k < n; ++k) {
      slots[k] = &variable(in, vr[k], type, what);
      check_settable(in, *slots[k], vr[k], what);
    }
    for (size_t k = 0; k < n; ++k) set(*slots[k], value[k]);
    return fmi2OK;
  });
}

}  // namespace
}  // namespace swarmcheck::fmi

using namespace swarmcheck::fmi;

FMI2_EXPORT const char* fmi2GetTypesPlatform(void) { return "default"; }
FMI2_EXPORT const char* fmi2GetVersion(void) { return "2.0"; }

FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t, const fmi2String[]) {
  auto* in = static_cast<Instance*>(c);
  if (!in) return fmi2Error;
  in->logging = on == fmi2True;
  return fmi2OK;
}

FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type type, fmi2String guid,
                                          fmi2String resourceLocation, const fmi2CallbackFunctions* functions,
                                          fmi2Boolean, fmi2Boolean loggingOn) {
  auto in = std::make_unique<Instance>();
  in->name = instanceName ? instanceName : "";
  if (functions) {
    in->logger = functions->logger;
    in->environment = functions->componentEnvironment;
  }
  in->logging = loggingOn == fmi2True;
  try {
    if (in->name.empty()) throw FmuError("fmi2Instantiate: instanceName must not be empty");
    if (type != fmi2CoSimulation) throw FmuError("fmi2Instantiate: this FMU supports co-simulation only");
    if (!resourceLocation) throw FmuError("fmi2Instantiate: fmuResourceLocation is null (the setup is in resources/)");
    const std::string path = path_of_uri(resourceLocation) + "swarmcheck-fmu.json";
    std::ifstream file(path, std::ios::binary);
    if (!file) throw FmuError("fmi2Instantiate: cannot read " + path);
    std::stringstream text;
    text << file.rdbuf();
    const FmuSetup setup = setup_from_json(text.str());
    const std::string expected = fmu_guid(setup);
    if (!guid || expected != guid)
      throw FmuError("fmi2Instantiate: GUID " + std::string(guid ? guid : "(null)") + " is not this FMU's " + expected +
                     " (modelDescription.xml and resources/ come from different exports)");
    in->component = make_component(setup);
    in->slots = in->component->table().slots().data();
    in->slot_count = static_cast<uint32_t>(in->component->table().slots().size());
  } catch (const std::exception& e) {
    log(in.get(), fmi2Error, "logError", e.what());
    return nullptr;
  }
  return in.release();
}

FMI2_EXPORT void fmi2FreeInstance(fmi2Component c) { delete static_cast<Instance*>(c); }

FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real startTime, fmi2Boolean,
                                           fmi2Real) {
  return guarded(c, "fmi2SetupExperiment", {Phase::instantiated}, [&](Instance& in) {
    in.time_s = startTime;
    in.component->start_at(startTime);
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  return guarded(c, "fmi2EnterInitializationMode", {Phase::instantiated}, [&](Instance& in) {
    in.phase = Phase::initialization;
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  return guarded(c, "fmi2ExitInitializationMode", {Phase::initialization}, [&](Instance& in) {
    in.component->initialize();
    in.phase = Phase::stepping;
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c) {
  return guarded(c, "fmi2Terminate", {Phase::stepping, Phase::initialization}, [&](Instance& in) {
    in.phase = Phase::terminated;
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c) {
  return guarded(c, "fmi2Reset",
                 {Phase::instantiated, Phase::initialization, Phase::stepping, Phase::terminated, Phase::failed},
                 [&](Instance& in) {
                   in.component->defaults();
                   in.phase = Phase::instantiated;
                   in.time_s = 0;
                   return fmi2OK;
                 });
}

FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
  return get_values(c, vr, n, value, BaseType::real, "fmi2GetReal", [](const VariableTable::Slot& v) { return v.real(); });
}
FMI2_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer value[]) {
  return get_values(c, vr, n, value, BaseType::integer, "fmi2GetInteger",
                    [](const VariableTable::Slot& v) { return v.integer(); });
}
FMI2_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2Boolean[]) {
  return guarded(c, "fmi2GetBoolean", {Phase::initialization, Phase::stepping, Phase::terminated, Phase::failed},
                 [&](Instance&) -> fmi2Status {
                   if (n == 0) return fmi2OK;
                   throw FmuError("this FMU has no Boolean variables");
                 });
}
FMI2_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2String[]) {
  return guarded(c, "fmi2GetString", {Phase::initialization, Phase::stepping, Phase::terminated, Phase::failed},
                 [&](Instance&) -> fmi2Status {
                   if (n == 0) return fmi2OK;
                   throw FmuError("this FMU has no String variables");
                 });
}

FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real value[]) {
  return set_values(c, vr, n, value, BaseType::real, "fmi2SetReal", [](const VariableTable::Slot& v, double x) { v.real() = x; });
}
FMI2_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                      const fmi2Integer value[]) {
  return set_values(c, vr, n, value, BaseType::integer, "fmi2SetInteger",
                    [](const VariableTable::Slot& v, int x) { v.integer() = x; });
}
FMI2_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2Boolean[]) {
  return guarded(c, "fmi2SetBoolean", {Phase::instantiated, Phase::initialization, Phase::stepping},
                 [&](Instance&) -> fmi2Status {
                   if (n == 0) return fmi2OK;
                   throw FmuError("this FMU has no Boolean variables");
                 });
}
FMI2_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2String[]) {
  return guarded(c, "fmi2SetString", {Phase::instantiated, Phase::initialization, Phase::stepping},
                 [&](Instance&) -> fmi2Status {
                   if (n == 0) return fmi2OK;
                   throw FmuError("this FMU has no String variables");
                 });
}

static constexpr std::initializer_list<Phase> kAnyLivePhase = {Phase::instantiated, Phase::initialization,
                                                               Phase::stepping, Phase::terminated};

FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate* state) {
  return guarded(c, "fmi2GetFMUstate", kAnyLivePhase, [&](Instance& in) {
    if (!state) throw FmuError("null FMUstate pointer");
    auto* saved = static_cast<SavedState*>(*state);
    if (!saved) saved = new SavedState;
    in.component->settle();
    saved->bytes = in.component->save();
    saved->phase = in.phase;
    saved->time_s = in.time_s;
    *state = saved;
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state) {
  return guarded(c, "fmi2SetFMUstate", kAnyLivePhase, [&](Instance& in) {
    const auto* saved = static_cast<const SavedState*>(state);
    if (!saved) throw FmuError("null FMUstate");
    in.component->restore(saved->bytes);
    in.phase = saved->phase;
    in.time_s = saved->time_s;
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate* state) {
  if (!c) return fmi2Error;
  if (state) {
    delete static_cast<SavedState*>(*state);
    *state = nullptr;
  }
  return fmi2OK;
}

namespace {
// A serialized state: phase (1 byte), time (8 bytes), then the component's bytes.
std::vector<uint8_t> serialized(const SavedState& s) {
  std::vector<uint8_t> out;
  out.push_back(static_cast<uint8_t>(s.phase));
  uint64_t t;
  std::memcpy(&t, &s.time_s, 8);
  for (int k = 0; k < 8; ++k) out.push_back(static_cast<uint8_t>(t >> (8 * k)));
  out.insert(out.end(), s.bytes.begin(), s.bytes.end());
  return out;
}
}  // namespace

FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, size_t* size) {
  return guarded(c, "fmi2SerializedFMUstateSize", kAnyLivePhase, [&](Instance&) {
    if (!state || !size) throw FmuError("null argument");
    *size = serialized(*static_cast<const SavedState*>(state)).size();
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], size_t size) {
  return guarded(c, "fmi2SerializeFMUstate", kAnyLivePhase, [&](Instance&) {
    if (!state || !bytes) throw FmuError("null argument");
    const std::vector<uint8_t> out = serialized(*static_cast<const SavedState*>(state));
    if (size < out.size()) throw FmuError("the buffer holds " + std::to_string(size) + " bytes, the state " + std::to_string(out.size()));
    std::memcpy(bytes, out.data(), out.size());
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], size_t size, fmi2FMUstate* state) {
  return guarded(c, "fmi2DeSerializeFMUstate", kAnyLivePhase, [&](Instance& in) {
    if (!bytes || !state) throw FmuError("null argument");
    if (size < 9 || static_cast<uint8_t>(bytes[0]) > static_cast<uint8_t>(Phase::terminated))
      throw FmuError("not a serialized state of this FMU");
    auto saved = std::make_unique<SavedState>();
    saved->phase = static_cast<Phase>(static_cast<uint8_t>(bytes[0]));
    uint64_t t = 0;
    for (int k = 0; k < 8; ++k) t |= uint64_t{static_cast<uint8_t>(bytes[1 + k])} << (8 * k);
    std::memcpy(&saved->time_s, &t, 8);
    saved->bytes.assign(reinterpret_cast<const uint8_t*>(bytes) + 9, reinterpret_cast<const uint8_t*>(bytes) + size);
    // Check the bytes now (on a copy of the instance's state), not when the master restores them.
    in.component->settle();
    const std::vector<uint8_t> current = in.component->save();
    in.component->restore(saved->bytes);
    in.component->restore(current);
    delete static_cast<SavedState*>(*state);
    *state = saved.release();
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                                    const fmi2ValueReference[], size_t, const fmi2Real[], fmi2Real[]) {
  return fail(static_cast<Instance*>(c), "fmi2GetDirectionalDerivative: not provided (providesDirectionalDerivative=false)");
}
FMI2_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                                   const fmi2Integer[], const fmi2Real[]) {
  return fail(static_cast<Instance*>(c), "fmi2SetRealInputDerivatives: not supported (canInterpolateInputs=false)");
}
FMI2_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                                    const fmi2Integer[], fmi2Real[]) {
  return fail(static_cast<Instance*>(c), "fmi2GetRealOutputDerivatives: not supported (maxOutputDerivativeOrder=0)");
}

FMI2_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean) {
  return guarded(c, "fmi2DoStep", {Phase::stepping}, [&](Instance& in) {
    if (!(h > 0)) throw FmuError("communicationStepSize must be > 0");
    in.component->step(t, h);
    in.time_s = t + h;
    return fmi2OK;
  });
}

FMI2_EXPORT fmi2Status fmi2CancelStep(fmi2Component c) {
  return fail(static_cast<Instance*>(c), "fmi2CancelStep: doStep never returns fmi2Pending here");
}

FMI2_EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status* status) {
  return guarded(c, "fmi2GetStatus", kAnyLivePhase, [&](Instance&) {
    if (status) *status = fmi2OK;
    return fmi2OK;
  });
}
FMI2_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real* value) {
  return guarded(c, "fmi2GetRealStatus", kAnyLivePhase, [&](Instance& in) {
    if (kind != fmi2LastSuccessfulTime || !value) throw FmuError("only fmi2LastSuccessfulTime is a Real status");
    *value = in.time_s;
    return fmi2OK;
  });
}
FMI2_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*) {
  return fail(static_cast<Instance*>(c), "fmi2GetIntegerStatus: no Integer status");
}
FMI2_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Boolean* value) {
  return guarded(c, "fmi2GetBooleanStatus", kAnyLivePhase, [&](Instance&) {
    if (kind != fmi2Terminated || !value) throw FmuError("only fmi2Terminated is a Boolean status");
    *value = fmi2False;
    return fmi2OK;
  });
}
FMI2_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*) {
  return fail(static_cast<Instance*>(c), "fmi2GetStringStatus: no String status");
}
