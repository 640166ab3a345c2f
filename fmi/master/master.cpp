#include "fmi/master/master.hpp"

#include <bit>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <map>

#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi::master {

// What an instance last logged (the message an error report quotes).
struct LogSink {
  std::string last_error;
  std::string last;
};

namespace {

void logger(fmi2ComponentEnvironment env, fmi2String, fmi2Status status, fmi2String, fmi2String message, ...) {
  if (!env || !message) return;
  char text[2048];
  va_list args;
  va_start(args, message);
  std::vsnprintf(text, sizeof text, message, args);
  va_end(args);
  auto* sink = static_cast<LogSink*>(env);
  sink->last = text;
  if (status == fmi2Error || status == fmi2Fatal) sink->last_error = text;
}

const char* status_name(int s) {
  switch (s) {
    case fmi2OK: return "fmi2OK";
    case fmi2Warning: return "fmi2Warning";
    case fmi2Discard: return "fmi2Discard";
    case fmi2Error: return "fmi2Error";
    case fmi2Fatal: return "fmi2Fatal";
    case fmi2Pending: return "fmi2Pending";
  }
  return "an unknown status";
}

}  // namespace

struct Master::Instance {
  std::string fmu_key, name, label;
  const FmuLibrary* library = nullptr;
  fmi2Component component = nullptr;
  LogSink sink;
  fmi2CallbackFunctions callbacks;
  // The outputs other instances read (one fmi2Get call per type per step), and the inputs set.
  std::vector<fmi2ValueReference> source_real_vr, source_int_vr, target_real_vr, target_int_vr;
  std::vector<double> source_real, target_real;
  std::vector<int> source_int, target_int;
  std::vector<std::size_t> links_in;   // the links into this instance
  // Inputs changed since they were last set (Jacobi sets only those: an FMU keeps an input's value
  // until it is set again, FMI 2.0 section 4.2.1). True at first: every input is set once.
  bool real_inputs_changed = true, int_inputs_changed = true;
  Instance() : callbacks{logger, nullptr, nullptr, nullptr, &sink} {}
};

struct Master::Link {
  std::size_t from = 0, to = 0;
  VarType type = VarType::real;
  std::size_t from_slot = 0, to_slot = 0;   // in the source's source_* and the target's target_* arrays
};

void Master::fail(int status, const Instance& in, const std::string& call) const {
  if (status == fmi2Warning) return;
  const std::string logged = in.sink.last_error.empty() ? in.sink.last : in.sink.last_error;
  throw InputError(in.library->path() + ": instance " + in.label,
                   call + " returned " + status_name(status) + (logged.empty() ? "" : ": " + logged));
}

Master::Master(const MultiModel& mm, const CoSimConfig& config, Algorithm algorithm)
    : algorithm_(algorithm), config_(config) {
  total_steps_ = std::llround((config.end_s - config.start_s) / config.step_s);
  std::map<std::string, const FmuLibrary*> library_of;
  for (const auto& [key, file] : mm.fmus) {
    libraries_.push_back(std::make_unique<FmuLibrary>(file));
    library_of[key] = libraries_.back().get();
  }
  std::map<std::string, std::size_t> index_of;   // "{FMU}.instance"
  for (const auto& [key, name] : mm.instances) {
    auto in = std::make_unique<Instance>();
    in->fmu_key = key;
    in->name = name;
    in->label = key + "." + name;
    in->library = library_of.at(key);
    index_of[in->label] = instances_.size();
    instances_.push_back(std::move(in));
  }
  const auto variable = [&](const PortName& p, const std::string& where) -> std::pair<std::size_t, const ModelVariable*> {
    const std::size_t k = index_of.at(p.fmu + "." + p.instance);
    const ModelVariable* v = instances_[k]->library->description().find(p.variable);
    if (!v)
      throw InputError(mm.file + ": " + where,
                       p.fmu + " (" + instances_[k]->library->path() + ") has no variable " + p.variable);
    return {k, v};
  };
  for (const Connection& c : mm.connections) {
    const auto [from, out] = variable(c.from, "connections." + c.from.text());
    const auto [to, in] = variable(c.to, c.where);
    if (out->causality != "output")
      throw InputError(mm.file + ": connections." + c.from.text(), c.from.variable + " is " + out->causality + ", not an output");
    if (in->causality != "input")
      throw InputError(mm.file + ": " + c.where, c.to.variable + " is " + in->causality + ", not an input");
    if (out->type != in->type)
      throw InputError(mm.file + ": " + c.where, std::string("type mismatch: ") + c.from.text() + " is " +
                                                     to_string(out->type) + ", " + c.to.text() + " is " + to_string(in->type));
    if (out->type != VarType::real && out->type != VarType::integer)
      throw InputError(mm.file + ": " + c.where, std::string("this master connects Real and Integer variables, not ") +
                                                     to_string(out->type));
    Link link{from, to, out->type, 0, 0};
    Instance& src = *instances_[from];
    Instance& dst = *instances_[to];
    auto& src_vr = out->type == VarType::real ? src.source_real_vr : src.source_int_vr;
    link.from_slot = src_vr.size();
    for (std::size_t s = 0; s < src_vr.size(); ++s)
      if (src_vr[s] == out->value_reference) link.from_slot = s;
    if (link.from_slot == src_vr.size()) src_vr.push_back(out->value_reference);
    auto& dst_vr = out->type == VarType::real ? dst.target_real_vr : dst.target_int_vr;
    link.to_slot = dst_vr.size();
    dst_vr.push_back(in->value_reference);
    dst.links_in.push_back(links_.size());
    links_.push_back(link);
  }
  for (auto& in : instances_) {
    in->source_real.resize(in->source_real_vr.size());
    in->source_int.resize(in->source_int_vr.size());
    in->target_real.resize(in->target_real_vr.size());
    in->target_int.resize(in->target_int_vr.size());
  }
  for (const Link& l : links_) {   // the buffers keep their addresses from here on
    Instance& src = *instances_[l.from];
    Instance& dst = *instances_[l.to];
    if (l.type == VarType::real)
      real_copies_.push_back({&src.source_real[l.from_slot], &dst.target_real[l.to_slot], &dst.real_inputs_changed});
    else
      int_copies_.push_back({&src.source_int[l.from_slot], &dst.target_int[l.to_slot], &dst.int_inputs_changed});
  }
  for (const Parameter& p : mm.parameters) {
    const auto [k, v] = variable(p.port, p.where);
    if (v->causality != "parameter" && v->causality != "input")
      throw InputError(mm.file + ": " + p.where, p.port.variable + " is " + v->causality + ", not a parameter or an input");
    if (v->type == VarType::string) throw InputError(mm.file + ": " + p.where, "String parameters are not supported");
    if (v->type != VarType::real && !p.integral)
      throw InputError(mm.file + ": " + p.where, p.port.variable + " is " + to_string(v->type) + ": expected an integer");
  }
  // Instantiate, parameters, initialisation; on a failure, every instance made so far is freed
  // before the libraries close (the destructor does not run for a constructor that throws).
  try {
    start(mm, config);
  } catch (...) {
    release();
    throw;
  }
  for (std::size_t k = 0; k < instances_.size(); ++k) {
    for (const ModelVariable& v : instances_[k]->library->description().variables) {
      if (v.causality != "output" || (v.type != VarType::real && v.type != VarType::integer)) continue;
      output_names_.push_back(instances_[k]->label + "." + v.name);
      outputs_.push_back(Port{k, v.value_reference, v.type});
    }
  }
}

void Master::start(const MultiModel& mm, const CoSimConfig& config) {
  const auto variable = [&](const PortName& p) -> std::pair<std::size_t, const ModelVariable*> {
    for (std::size_t k = 0; k < instances_.size(); ++k)
      if (instances_[k]->fmu_key == p.fmu && instances_[k]->name == p.instance)
        return {k, instances_[k]->library->description().find(p.variable)};
    return {0, nullptr};
  };
  for (auto& in : instances_) {
    const ModelDescription& md = in->library->description();
    in->component = in->library->api().instantiate(in->label.c_str(), fmi2CoSimulation, md.guid.c_str(),
                                                   in->library->resource_uri().c_str(), &in->callbacks, fmi2False, fmi2False);
    if (!in->component)
      throw InputError(in->library->path() + ": instance " + in->label,
                       "fmi2Instantiate failed" + (in->sink.last.empty() ? std::string() : ": " + in->sink.last));
    check(in->library->api().setup_experiment(in->component, fmi2False, 0.0, config.start_s, fmi2True, config.end_s), *in,
          "fmi2SetupExperiment");
  }
  for (const Parameter& p : mm.parameters) {
    const auto [k, v] = variable(p.port);   // checked in the constructor
    Instance& in = *instances_[k];
    const fmi2ValueReference vr = v->value_reference;
    int status = fmi2OK;
    if (v->type == VarType::real) {
      const double x = p.value;
      status = in.library->api().set_real(in.component, &vr, 1, &x);
    } else if (v->type == VarType::integer) {
      const int x = static_cast<int>(p.value);
      status = in.library->api().set_integer(in.component, &vr, 1, &x);
    } else {
      const int x = p.value != 0 ? fmi2True : fmi2False;
      status = in.library->api().set_boolean(in.component, &vr, 1, &x);
    }
    if (status != fmi2OK) fail(status, in, "setting parameter " + p.port.variable + " (" + mm.file + ": " + p.where + ")");
  }
  for (auto& in : instances_)
    check(in->library->api().enter_initialization_mode(in->component), *in, "fmi2EnterInitializationMode");
  for (auto& in : instances_)
    check(in->library->api().exit_initialization_mode(in->component), *in, "fmi2ExitInitializationMode");
  for (auto& in : instances_) fetch_outputs(*in);
}

void Master::release() {
  for (auto& in : instances_) {
    if (!in->component) continue;
    in->library->api().terminate(in->component);
    in->library->api().free_instance(in->component);
    in->component = nullptr;
  }
}

Master::~Master() { release(); }

double Master::time_s() const { return config_.start_s + static_cast<double>(steps_) * config_.step_s; }

void Master::fetch_outputs(Instance& in) {
  const Fmi2Functions& api = in.library->api();
  if (!in.source_real_vr.empty())
    check(api.get_real(in.component, in.source_real_vr.data(), in.source_real_vr.size(), in.source_real.data()), in,
          "fmi2GetReal");
  if (!in.source_int_vr.empty())
    check(api.get_integer(in.component, in.source_int_vr.data(), in.source_int_vr.size(), in.source_int.data()), in,
          "fmi2GetInteger");
}

// Sets the target's inputs from its sources' outputs as they are now, fetched one by one
// (Gauss-Seidel: a source stepped earlier in this step shows its new value).
void Master::set_inputs(std::size_t target) {
  Instance& dst = *instances_[target];
  for (const std::size_t li : dst.links_in) {
    const Link& l = links_[li];
    Instance& src = *instances_[l.from];
    if (l.type == VarType::real) {
      check(src.library->api().get_real(src.component, &src.source_real_vr[l.from_slot], 1, &src.source_real[l.from_slot]),
              src, "fmi2GetReal");
      dst.target_real[l.to_slot] = src.source_real[l.from_slot];
    } else {
      check(src.library->api().get_integer(src.component, &src.source_int_vr[l.from_slot], 1, &src.source_int[l.from_slot]),
              src, "fmi2GetInteger");
      dst.target_int[l.to_slot] = src.source_int[l.from_slot];
    }
  }
  push_inputs(dst, false);
}

void Master::push_inputs(Instance& dst, bool only_changed) {
  const Fmi2Functions& api = dst.library->api();
  if (!dst.target_real_vr.empty() && (dst.real_inputs_changed || !only_changed))
    check(api.set_real(dst.component, dst.target_real_vr.data(), dst.target_real_vr.size(), dst.target_real.data()), dst,
          "fmi2SetReal");
  if (!dst.target_int_vr.empty() && (dst.int_inputs_changed || !only_changed))
    check(api.set_integer(dst.component, dst.target_int_vr.data(), dst.target_int_vr.size(), dst.target_int.data()), dst,
          "fmi2SetInteger");
  dst.real_inputs_changed = dst.int_inputs_changed = false;
}

void Master::step() {
  const double t = time_s();
  const auto do_step = [&](Instance& in) {
    const int status = in.library->api().do_step(in.component, t, config_.step_s, fmi2True);
    if (status == fmi2OK) return;
    char when[64];
    std::snprintf(when, sizeof when, "fmi2DoStep at t = %.17g s", t);
    fail(status, in, when);
  };
  if (algorithm_ == Algorithm::jacobi) {
    // The source buffers hold every output as of t (fetched after each instance's last step, or
    // after initialisation): copied to the inputs first, so stepping one instance cannot change
    // another's inputs. Each instance is then set, stepped and read in one visit (its data stays
    // in the cache).
    for (const Copy<double>& c : real_copies_) {
      if (std::bit_cast<uint64_t>(*c.to) == std::bit_cast<uint64_t>(*c.from)) continue;
      *c.to = *c.from;
      *c.changed = true;
    }
    for (const Copy<int>& c : int_copies_) {
      if (*c.to == *c.from) continue;
      *c.to = *c.from;
      *c.changed = true;
    }
    for (auto& in : instances_) {
      push_inputs(*in, true);
      do_step(*in);
      fetch_outputs(*in);
    }
  } else {
    for (std::size_t k = 0; k < instances_.size(); ++k) {
      set_inputs(k);
      do_step(*instances_[k]);
    }
  }
  ++steps_;
}

Master::Port Master::port(const std::string& name) const {
  for (std::size_t k = 0; k < instances_.size(); ++k) {
    const std::string& label = instances_[k]->label;
    if (name.size() <= label.size() + 1 || name.compare(0, label.size(), label) != 0 || name[label.size()] != '.') continue;
    const ModelVariable* v = instances_[k]->library->description().find(name.substr(label.size() + 1));
    if (v) return Port{k, v->value_reference, v->type};
  }
  throw InputError(name, "no such instance variable in the multi-model");
}

double Master::value(const Port& p) const {
  const Instance& in = *instances_[p.instance];
  const Fmi2Functions& api = in.library->api();
  if (p.type == VarType::real) {
    double x = 0;
    check(api.get_real(in.component, &p.value_reference, 1, &x), in, "fmi2GetReal");
    return x;
  }
  int x = 0;
  if (p.type == VarType::integer) check(api.get_integer(in.component, &p.value_reference, 1, &x), in, "fmi2GetInteger");
  else if (p.type == VarType::boolean) check(api.get_boolean(in.component, &p.value_reference, 1, &x), in, "fmi2GetBoolean");
  else throw InputError(in.label, "String variables are not read by this master");
  return x;
}

void Master::output_values(std::vector<double>& out) const {
  out.resize(outputs_.size());
  for (std::size_t k = 0; k < outputs_.size(); ++k) out[k] = value(outputs_[k]);
}

std::vector<std::string> Master::instance_names() const {
  std::vector<std::string> out;
  for (const auto& in : instances_) out.push_back(in->label);
  return out;
}

const std::string& Master::model_name_of(const std::string& instance) const {
  for (const auto& in : instances_)
    if (in->label == instance) return in->library->description().model_name;
  throw InputError(instance, "no such instance");
}

}  // namespace swarmcheck::fmi::master
