// Each FMU through the whole fmi2 life cycle, loaded as a master loads it (unzipped, dlopen):
// several instances per process, initialisation, get/set, doStep, state save/restore and
// serialization (a restored state continues with the same bits), reset, terminate, free; and
// every misuse an fmi2Error with a logged message, never a crash (the debug build runs this under
// ASan and UBSan).
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdarg>
#include <cstring>

#include "fmi/master/fmu_library.hpp"
#include "spec/exploration/scenario.hpp"
#include "tests/fmi/scratch.hpp"

namespace {

using namespace swarmcheck;
using fmi::master::FmuLibrary;

struct Log {
  std::vector<std::string> errors;
};

void log_message(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String, fmi2String message, ...) {
  char text[2048];
  va_list args;
  va_start(args, message);
  std::vsnprintf(text, sizeof text, message, args);
  va_end(args);
  if (status == fmi2Error || status == fmi2Fatal) static_cast<Log*>(env)->errors.emplace_back(text);
}

class Fmu {
 public:
  Fmu(const FmuLibrary& lib, const std::string& name, Log& log)
      : lib_(lib), callbacks_{log_message, nullptr, nullptr, nullptr, &log} {
    c_ = lib.api().instantiate(name.c_str(), fmi2CoSimulation, lib.description().guid.c_str(), lib.resource_uri().c_str(),
                               &callbacks_, fmi2False, fmi2False);
  }
  ~Fmu() {
    if (c_) lib_.api().free_instance(c_);
  }
  fmi2Component c() const { return c_; }
  fmi2ValueReference vr(const std::string& name) const { return lib_.description().find(name)->value_reference; }
  double real(const std::string& name) const {
    double v = 0;
    const fmi2ValueReference r = vr(name);
    EXPECT_EQ(lib_.api().get_real(c_, &r, 1, &v), fmi2OK) << name;
    return v;
  }
  int integer(const std::string& name) const {
    int v = 0;
    const fmi2ValueReference r = vr(name);
    EXPECT_EQ(lib_.api().get_integer(c_, &r, 1, &v), fmi2OK) << name;
    return v;
  }
  fmi2Status set(const std::string& name, double v) const {
    const fmi2ValueReference r = vr(name);
    return lib_.api().set_real(c_, &r, 1, &v);
  }
  fmi2Status set_int(const std::string& name, int v) const {
    const fmi2ValueReference r = vr(name);
    return lib_.api().set_integer(c_, &r, 1, &v);
  }
  fmi2Status init() const {
    if (lib_.api().setup_experiment(c_, fmi2False, 0, 0, fmi2False, 0) != fmi2OK) return fmi2Error;
    if (lib_.api().enter_initialization_mode(c_) != fmi2OK) return fmi2Error;
    return lib_.api().exit_initialization_mode(c_);
  }
  fmi2Status step(double t, double h) const { return lib_.api().do_step(c_, t, h, fmi2True); }
  // Every Real and Integer variable's bits.
  std::vector<uint64_t> snapshot() const {
    std::vector<uint64_t> out;
    for (const auto& v : lib_.description().variables) {
      if (v.type == fmi::master::VarType::real) out.push_back(std::bit_cast<uint64_t>(real(v.name)));
      else out.push_back(static_cast<uint64_t>(integer(v.name)));
    }
    return out;
  }

 private:
  const FmuLibrary& lib_;
  fmi2CallbackFunctions callbacks_;
  fmi2Component c_ = nullptr;
};

struct Loaded {
  std::filesystem::path dir = swarmcheck::testing::fmi_scratch("lifecycle");
  FmuLibrary environment{swarmcheck::testing::export_fmu(dir, fmi::Kind::environment, exploration::default_scenario())};
  FmuLibrary controller{swarmcheck::testing::export_fmu(dir, fmi::Kind::controller, exploration::default_scenario())};
  FmuLibrary body{swarmcheck::testing::export_fmu(dir, fmi::Kind::body, exploration::default_scenario())};
  // The thesis interface's Controller (Real ports) and Body (the 20-sim body's memory in its state).
  FmuLibrary thesis_controller{thesis_fmu(dir, fmi::Kind::controller, "UController.fmu")};
  FmuLibrary intocps_body{thesis_fmu(dir, fmi::Kind::body, "Body_Block1.fmu")};

  static std::string thesis_fmu(const std::filesystem::path& dir, fmi::Kind kind, const std::string& file) {
    const std::string path = (dir / file).string();
    fmi::write_fmu(fmi::fmu_setup(kind, fmi::thesis_interface_scenario(), fmi::Interface::thesis), path);
    return path;
  }
};

Loaded& loaded() {
  static Loaded l;
  return l;
}

}  // namespace

TEST(FmiLifecycle, TwoEnvironmentInstancesInOneProcessStepIndependently) {
  Log log;
  Fmu a(loaded().environment, "a", log), b(loaded().environment, "b", log);
  ASSERT_NE(a.c(), nullptr);
  ASSERT_NE(b.c(), nullptr);
  ASSERT_EQ(b.set_int("mapSize", 12), fmi2OK);
  ASSERT_EQ(a.init(), fmi2OK);
  ASSERT_EQ(b.init(), fmi2OK);
  for (int k = 0; k < 3; ++k) {
    ASSERT_EQ(a.step(k * 0.1, 0.1), fmi2OK);
  }
  EXPECT_EQ(a.integer("stepCount"), 3);
  EXPECT_EQ(b.integer("stepCount"), 0);
  EXPECT_EQ(a.integer("planningSteps"), 2);   // inputs held at 1: the flag handshake plans every other step
  EXPECT_EQ(b.integer("mapSize"), 12);
  EXPECT_TRUE(log.errors.empty());
}

TEST(FmiLifecycle, ARestoredOrDeserializedStateContinuesWithTheSameBits) {
  for (FmuLibrary* lib : {&loaded().environment, &loaded().controller, &loaded().body, &loaded().thesis_controller,
                          &loaded().intocps_body}) {
    Log log;
    Fmu f(*lib, "f", log);
    ASSERT_EQ(f.init(), fmi2OK) << lib->path();
    const auto drive = [&](int from, int steps) {
      for (int k = from; k < from + steps; ++k) {
        if (lib == &loaded().controller) {   // a waypoint to drive to and a pose that moves
          f.set("xDesired", 3.5), f.set("yDesired", 2.5), f.set("x", 0.5 + 0.01 * k);
          f.set_int("onDestinationInput", k % 7 == 0 ? 1 : 0);
        }
        if (lib == &loaded().thesis_controller) {
          f.set("xDesired", 3.5), f.set("yDesired", 2.5), f.set("x", 0.5 + 0.01 * k);
          f.set("onDestinationInput", k % 7 == 0 ? 1.0 : 0.0);
        }
        if (lib == &loaded().body || lib == &loaded().intocps_body)
          f.set("servo_left_input", 0.3), f.set("servo_right_input", -0.1 - 0.001 * k);
        if (lib == &loaded().environment) f.set_int("onDestination2Input", k % 5 == 0 ? 0 : 1);
        ASSERT_EQ(f.step(k * 0.1, 0.1), fmi2OK);
      }
    };
    drive(0, 20);
    fmi2FMUstate state = nullptr;
    ASSERT_EQ(lib->api().get_state(f.c(), &state), fmi2OK);
    drive(20, 200);
    const auto after = f.snapshot();
    ASSERT_EQ(lib->api().set_state(f.c(), state), fmi2OK);
    drive(20, 200);
    EXPECT_EQ(f.snapshot(), after) << lib->path();
    // Serialized to bytes and back: the same continuation again.
    std::size_t size = 0;
    ASSERT_EQ(lib->api().serialized_state_size(f.c(), state, &size), fmi2OK);
    std::vector<fmi2Byte> bytes(size);
    ASSERT_EQ(lib->api().serialize_state(f.c(), state, bytes.data(), bytes.size()), fmi2OK);
    fmi2FMUstate copy = nullptr;
    ASSERT_EQ(lib->api().deserialize_state(f.c(), bytes.data(), bytes.size(), &copy), fmi2OK);
    drive(220, 5);
    ASSERT_EQ(lib->api().set_state(f.c(), copy), fmi2OK);
    drive(20, 200);
    EXPECT_EQ(f.snapshot(), after) << lib->path();
    // Damaged bytes are refused, and the instance goes on.
    std::vector<fmi2Byte> damaged(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(bytes.size() / 2));
    fmi2FMUstate none = nullptr;
    EXPECT_EQ(lib->api().deserialize_state(f.c(), damaged.data(), damaged.size(), &none), fmi2Error);
    EXPECT_EQ(none, nullptr);
    EXPECT_FALSE(log.errors.empty());
    log.errors.clear();
    ASSERT_EQ(lib->api().free_state(f.c(), &copy), fmi2OK);
    ASSERT_EQ(lib->api().free_state(f.c(), &state), fmi2OK);
    EXPECT_EQ(state, nullptr);
    EXPECT_TRUE(log.errors.empty()) << log.errors.front();
    EXPECT_EQ(lib->api().reset(f.c()), fmi2OK);
    ASSERT_EQ(f.init(), fmi2OK);
    drive(0, 20);
    ASSERT_EQ(lib->api().reset(f.c()), fmi2OK);
  }
}

TEST(FmiLifecycle, MisuseIsAnFmi2ErrorWithALoggedMessageNeverACrash) {
  FmuLibrary& lib = loaded().environment;
  Log log;
  Fmu f(lib, "f", log);
  ASSERT_NE(f.c(), nullptr);
  EXPECT_EQ(f.step(0, 0.1), fmi2Error);   // before initialisation
  EXPECT_NE(log.errors.back().find("not allowed in instantiated"), std::string::npos) << log.errors.back();
  ASSERT_EQ(f.init(), fmi2OK);
  EXPECT_EQ(f.step(0, 0.15), fmi2Error);
  EXPECT_NE(log.errors.back().find("0.14999999999999999 s is not a whole multiple of step_size 0.10000000000000001 s"),
            std::string::npos)
      << log.errors.back();
  EXPECT_EQ(f.set("eP", 50), fmi2Error);   // an output
  EXPECT_EQ(f.set("a1", 2), fmi2Error);    // a fixed parameter after initialisation
  const fmi2ValueReference nowhere = 999999;
  double v = 0;
  EXPECT_EQ(lib.api().get_real(f.c(), &nowhere, 1, &v), fmi2Error);
  const fmi2ValueReference map_size = f.vr("mapSize");
  EXPECT_EQ(lib.api().get_real(f.c(), &map_size, 1, &v), fmi2Error);   // an Integer read as Real
  EXPECT_EQ(lib.api().get_boolean(f.c(), &map_size, 1, nullptr), fmi2Error);
  // A state of another FMU kind is refused when restored.
  Log other_log;
  Fmu body(loaded().body, "b", other_log);
  ASSERT_EQ(body.init(), fmi2OK);
  fmi2FMUstate body_state = nullptr;
  ASSERT_EQ(loaded().body.api().get_state(body.c(), &body_state), fmi2OK);
  EXPECT_EQ(lib.api().set_state(f.c(), body_state), fmi2Error);
  loaded().body.api().free_state(body.c(), &body_state);
  EXPECT_EQ(f.step(0, 0.1), fmi2OK);   // the refused restore left it working
  // Parameters that make no scenario fail at initialisation with the scenario's reason.
  Log bad_log;
  Fmu bad(lib, "bad", bad_log);
  ASSERT_EQ(bad.set_int("mapSize", 0), fmi2OK);
  EXPECT_EQ(bad.init(), fmi2Error);
  ASSERT_FALSE(bad_log.errors.empty());
  EXPECT_NE(bad_log.errors.back().find("map_size"), std::string::npos) << bad_log.errors.back();
  // Terminate, then reset: the start values again, and it initialises again.
  EXPECT_EQ(lib.api().terminate(f.c()), fmi2OK);
  EXPECT_EQ(f.step(0, 0.1), fmi2Error);
  EXPECT_EQ(lib.api().reset(f.c()), fmi2OK);
  ASSERT_EQ(f.init(), fmi2OK);
  EXPECT_EQ(f.integer("stepCount"), 0);
  ASSERT_EQ(dlsym(RTLD_DEFAULT, "fmi2Reset"), nullptr);   // the FMU's symbols stay local to it
}

// Masters that compute a step as t(k+1) - t(k) (fmusim, FMPy) give 0.10000000000000003 and the
// like for step_size 0.1: within a relative 1e-9 it is one Environment step; a whole multiple of
// step_size is that many steps.
TEST(FmiLifecycle, TheEnvironmentTakesStepsComputedAsDifferencesOfTimesOver100000StepsAndWholeMultiples) {
  FmuLibrary& lib = loaded().environment;
  Log log;
  for (const bool added : {false, true}) {   // t(k) = k h, or t(k+1) = t(k) + h
    Fmu f(lib, added ? "added" : "multiplied", log);
    ASSERT_EQ(f.init(), fmi2OK);
    double t = 0;
    int off_by_rounding = 0;
    for (int k = 0; k < 100000; ++k) {
      const double next = added ? t + 0.1 : (k + 1) * 0.1;
      const double h = next - t;
      off_by_rounding += h != 0.1;
      ASSERT_EQ(f.step(t, h), fmi2OK) << "step " << k << ": h = " << h << ": " << (log.errors.empty() ? "" : log.errors.back());
      t = next;
    }
    EXPECT_GT(off_by_rounding, 1000);   // the differences are not 0.1 (else this tests nothing)
    EXPECT_EQ(f.integer("stepCount"), 100000);
  }
  Fmu g(lib, "multiples", log);
  ASSERT_EQ(g.init(), fmi2OK);
  ASSERT_EQ(g.step(0, 0.30000000000000004), fmi2OK);
  EXPECT_EQ(g.integer("stepCount"), 3);
  ASSERT_EQ(g.step(0.3, 1.0), fmi2OK);
  EXPECT_EQ(g.integer("stepCount"), 13);
  EXPECT_EQ(g.step(1.3, 0.1 * (1 + 2e-9)), fmi2Error);   // beyond the tolerance
  EXPECT_EQ(g.step(1.3, 0.05), fmi2Error);               // half a step
  EXPECT_EQ(g.integer("stepCount"), 13);
  EXPECT_EQ(log.errors.size(), 2u);
}

TEST(FmiLifecycle, InstantiateRefusesAWrongGuidAModelExchangeRequestAndNoResources) {
  FmuLibrary& lib = loaded().controller;
  Log log;
  fmi2CallbackFunctions cb{log_message, nullptr, nullptr, nullptr, &log};
  EXPECT_EQ(lib.api().instantiate("x", fmi2CoSimulation, "{not-this}", lib.resource_uri().c_str(), &cb, 0, 0), nullptr);
  EXPECT_NE(log.errors.back().find("GUID"), std::string::npos);
  EXPECT_EQ(lib.api().instantiate("x", fmi2ModelExchange, lib.description().guid.c_str(), lib.resource_uri().c_str(), &cb, 0, 0),
            nullptr);
  EXPECT_NE(log.errors.back().find("co-simulation only"), std::string::npos);
  EXPECT_EQ(lib.api().instantiate("x", fmi2CoSimulation, lib.description().guid.c_str(), nullptr, &cb, 0, 0), nullptr);
  EXPECT_EQ(lib.api().instantiate("x", fmi2CoSimulation, lib.description().guid.c_str(), "file:///nowhere/", &cb, 0, 0), nullptr);
  EXPECT_NE(log.errors.back().find("cannot read"), std::string::npos);
  fmi2Component quiet =
      lib.api().instantiate("x", fmi2CoSimulation, lib.description().guid.c_str(), lib.resource_uri().c_str(), nullptr, 0, 0);
  EXPECT_NE(quiet, nullptr);   // no callbacks is allowed: it just cannot log
  lib.api().free_instance(quiet);
}
