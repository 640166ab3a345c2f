#pragma once
// The fixed-step co-simulation master for INTO-CPS multi-models (multimodel.hpp). One step at
// t_k = start + k h (k counted, never accumulated):
//   jacobi (Maestro's default): every connected input is set from the outputs as of t_k, then
//     every instance steps; so it is the master of `swarmcheck run --mode cosim`
//     (spec/exploration/master.hpp), and a swarmcheck multi-model gives that run's bits.
//   gauss-seidel: instance by instance in the multi-model's order, each input is set from its
//     source's latest output (an instance stepped before it in this step shows its new one), then
//     the instance steps.
// Any fmi2 call that returns fmi2Error or fmi2Fatal stops the run with an InputError carrying
// what the FMU logged.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fmi/master/fmu_library.hpp"
#include "fmi/master/multimodel.hpp"

namespace swarmcheck::fmi::master {

enum class Algorithm { jacobi, gauss_seidel };

class Master {
 public:
  // Loads the FMUs, checks every connection and parameter against their model descriptions,
  // instantiates, sets the parameters and initialises (the outputs are then those at start).
  Master(const MultiModel& mm, const CoSimConfig& config, Algorithm algorithm);
  ~Master();
  Master(const Master&) = delete;
  Master& operator=(const Master&) = delete;

  void step();
  bool done() const { return steps_ >= total_steps_; }
  int64_t steps() const { return steps_; }
  int64_t total_steps() const { return total_steps_; }
  double time_s() const;

  // A variable of an instance, for reading it every step.
  struct Port {
    std::size_t instance = 0;
    uint32_t value_reference = 0;
    VarType type = VarType::real;
  };
  Port port(const std::string& name) const;   // "{FMU}.instance.variable"; InputError if unknown
  double value(const Port& p) const;

  // Every output of every instance ("{FMU}.instance.variable"), instances in stepping order.
  const std::vector<std::string>& output_names() const { return output_names_; }
  void output_values(std::vector<double>& out) const;

  // The model name of the FMU an instance belongs to, and its instances' names.
  std::vector<std::string> instance_names() const;
  const std::string& model_name_of(const std::string& instance) const;

 private:
  struct Instance;
  struct Link;
  void check(int status, const Instance& in, const char* call) const {
    if (status != 0 /* fmi2OK */) fail(status, in, call);
  }
  void fail(int status, const Instance& in, const std::string& call) const;   // unless a warning: throws
  void start(const MultiModel& mm, const CoSimConfig& config);   // instantiate, parameters, initialise
  void release();                                               // terminate and free every instance
  void set_inputs(std::size_t target);
  void push_inputs(std::size_t target, bool only_changed);
  void fetch_outputs(std::size_t source);

  Algorithm algorithm_;
  CoSimConfig config_;
  int64_t steps_ = 0;
  int64_t total_steps_ = 0;
  std::vector<std::unique_ptr<FmuLibrary>> libraries_;
  std::vector<std::unique_ptr<Instance>> instances_;
  std::vector<Link> links_;
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
  std::vector<std::string> output_names_;
  std::vector<Port> outputs_;
};

}  // namespace swarmcheck::fmi::master
