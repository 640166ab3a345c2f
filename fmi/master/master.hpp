#pragma once
// The fixed-step co-simulation master for INTO-CPS multi-models (multimodel.hpp), doing what the
// INTO-CPS engine (the COE, Maestro 1) does, so that FMUs written for it give its results here:
//   start: every instance is instantiated and set up (fmi2SetupExperiment); then the start value
//     of each of its parameters and inputs (modelDescription.xml, overridden by the multi-model's
//     `parameters`) is written; then all enter and exit initialisation. (FMUs exported by tools
//     that do not apply their own start values, like the thesis's, rely on this.)
//   time: by repeated addition, t <- t + h, as the engine; after a step at t the next is taken
//     while t + h <= endTime. (So after 10^4 steps of 0.1 s, t differs from k h by about 1e-9.)
//   one step at t:
//     jacobi (Maestro's default): every connected input is set from the outputs as of t, then
//       every instance steps; so it is the master of `swarmcheck run --mode cosim`
//       (spec/exploration/master.hpp), and a swarmcheck multi-model gives that run's bits.
//     gauss-seidel: instance by instance in the multi-model's order, each input is set from its
//       source's latest output (an instance stepped before it in this step shows its new one), then
//       the instance steps.
//   instances: an FMU declaring canBeInstantiatedOnlyOncePerProcess gets one copy of its library
//     per instance (fmu_library.hpp).
// Any fmi2 call that returns fmi2Error or fmi2Fatal stops the run with an InputError carrying
// what the FMU logged. With a call time limit, a call that does not return within it stops the
// run with a CallTimeout naming the instance and the step (call_watchdog.hpp); the destructor then
// frees every instance and removes every unpacked folder, as after any other stop.
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fmi/master/call_watchdog.hpp"
#include "fmi/master/fmu_library.hpp"
#include "fmi/master/multimodel.hpp"

namespace swarmcheck::fmi::master {

enum class Algorithm { jacobi, gauss_seidel };

struct MasterOptions {
  Algorithm algorithm = Algorithm::jacobi;
  double call_limit_s = 0;   // wall-clock limit of one FMU call (a step, initialisation), s; 0: none
};

// An FMU call that did not return within the call time limit (what() names it).
class CallTimeout : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Master {
 public:
  // Loads the FMUs, checks every connection, parameter and logged variable against their model
  // descriptions, instantiates, writes the start values and initialises (the outputs are then
  // those at start).
  Master(const MultiModel& mm, const CoSimConfig& config, const MasterOptions& options = {});
  Master(const MultiModel& mm, const CoSimConfig& config, Algorithm algorithm)
      : Master(mm, config, MasterOptions{algorithm, 0}) {}
  ~Master();
  Master(const Master&) = delete;
  Master& operator=(const Master&) = delete;

  void step();
  bool done() const { return steps_ >= total_steps_; }
  int64_t steps() const { return steps_; }
  int64_t total_steps() const { return total_steps_; }
  double time_s() const { return time_s_; }
  double step_size_s() const { return config_.step_s; }

  // A variable of an instance, for reading it every step.
  struct Port {
    std::size_t instance = 0;
    uint32_t value_reference = 0;
    VarType type = VarType::real;
  };
  Port port(const std::string& name) const;   // "{FMU}.instance.variable"; InputError if unknown
  double value(const Port& p) const;          // Real, Integer, Boolean (1 / 0)
  std::string text(const Port& p) const;      // String

  // What the engine records in outputs.csv: every connected output and every variable of the
  // configuration's logVariables, once each, sorted by name ("{FMU}.instance.variable").
  const std::vector<std::string>& recorded_names() const { return recorded_names_; }
  const std::vector<Port>& recorded_ports() const { return recorded_; }

  // The model name of the FMU an instance belongs to, and its instances' names.
  std::vector<std::string> instance_names() const;
  const std::string& model_name_of(const std::string& instance) const;

  // A file to remove if the process has to end while an FMU call cannot be left (call_watchdog.hpp).
  void remove_if_abandoned(const std::string& path) { watchdog_->remove_if_abandoned(path); }

 private:
  struct Instance;
  struct Link;
  void check(int status, const Instance& in, const char* call) const {
    if (status != 0 /* fmi2OK */) fail(status, in, call);
  }
  void fail(int status, const Instance& in, const std::string& call) const;   // unless a warning: throws
  void connect(const MultiModel& mm, const std::map<std::string, std::size_t>& index_of);
  void record(const MultiModel& mm, const CoSimConfig& config, const std::map<std::string, std::size_t>& index_of);
  void start(const MultiModel& mm);          // instantiate, start values, initialise
  void write_start_values(std::size_t k, const MultiModel& mm, const std::vector<const Parameter*>& parameters);
  void release();                            // terminate and free every instance
  // An FMU call under the time limit: CallTimeout when it is cut off.
  template <class F>
  int call(std::size_t instance, const char* what, F&& f);
  std::string describe(std::size_t instance, const char* what) const;
  void set_inputs(std::size_t target);
  void push_inputs(std::size_t target, bool only_changed);
  void fetch_outputs(std::size_t source);

  MasterOptions options_;
  CoSimConfig config_;
  int64_t steps_ = 0;
  int64_t total_steps_ = 0;
  double time_s_ = 0;
  bool initialised_ = false;
  std::vector<std::unique_ptr<FmuLibrary>> libraries_;
  std::vector<std::unique_ptr<Instance>> instances_;
  std::vector<Link> links_;
  std::unique_ptr<CallWatchdog> watchdog_;
  // What a step touches, contiguous and in stepping order, so an instance's data is a few cache
  // lines (the step is bound by memory latency, not by arithmetic, at 100s of instances).
  //   hot_[k]: instance k's component, its library's functions, and its slices of the arrays
  //   below: the outputs other instances read (src_*), the inputs it is given (tgt_*).
  struct Slice {
    uint32_t begin = 0, size = 0;
  };
  struct Hot {
    void* component = nullptr;
    const Fmi2Functions* api = nullptr;
    Slice src_real, src_int, tgt_real, tgt_int;
    // Inputs changed since they were last set (Jacobi sets only those: an FMU keeps an input's
    // value until it is set again, FMI 2.0 section 4.2.1). True at first: every input is set once.
    bool real_changed = true, int_changed = true;
  };
  std::vector<Hot> hot_;
  std::vector<uint32_t> src_real_vr_, src_int_vr_, tgt_real_vr_, tgt_int_vr_;
  std::vector<double> src_real_, tgt_real_;
  std::vector<int> src_int_, tgt_int_;
  // Jacobi's copies, source value to target input (indices into the arrays above), by target.
  struct Copy {
    uint32_t from, to, target;
  };
  std::vector<Copy> real_copies_, int_copies_;
  std::vector<std::string> recorded_names_;
  std::vector<Port> recorded_;
};

}  // namespace swarmcheck::fmi::master
