#include "fmi/master/master.hpp"

#include <algorithm>
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
  FmuLibrary* library = nullptr;
  const Fmi2Functions* api = nullptr;   // of the copy of the library this instance uses
  fmi2Component component = nullptr;
  bool stuck = false;   // a call of it never returned: it is not called again
  LogSink sink;
  fmi2CallbackFunctions callbacks;
  // While connecting: the value references of the outputs other instances read and of the inputs
  // set, by type (the step reads them from the contiguous arrays of Master::Buffers).
  std::vector<fmi2ValueReference> source_real_vr, source_int_vr, target_real_vr, target_int_vr;
  std::vector<std::size_t> links_in;   // the links into this instance
  Instance() : callbacks{logger, nullptr, nullptr, nullptr, &sink} {}
};

struct Master::Link {
  std::size_t from = 0, to = 0;
  VarType type = VarType::real;
  std::size_t from_slot = 0, to_slot = 0;   // in the source's source_* and the target's target_* lists
};

void Master::fail(int status, const Instance& in, const std::string& call) const {
  if (status == fmi2Warning) return;
  const std::string logged = in.sink.last_error.empty() ? in.sink.last : in.sink.last_error;
  throw InputError(in.library->path() + ": instance " + in.label,
                   call + " returned " + status_name(status) + (logged.empty() ? "" : ": " + logged));
}

std::string Master::describe(std::size_t instance, const char* what) const {
  const Instance& in = *instances_[instance];
  char when[96];
  if (!initialised_) std::snprintf(when, sizeof when, "at initialisation");
  else if (std::string_view(what) == "fmi2DoStep")
    std::snprintf(when, sizeof when, "at step %lld (t = %.17g s)", static_cast<long long>(steps_ + 1), time_s_);
  else std::snprintf(when, sizeof when, "after step %lld", static_cast<long long>(steps_));
  return in.label + " (" + in.library->path() + "): " + what + " " + when;
}

template <class F>
int Master::call(std::size_t instance, const char* what, F&& f) {
  int status = fmi2OK;
  if (!watchdog_->run(CallWatchdog::Call{instance, what}, f, status)) {
    instances_[instance]->stuck = true;
    char limit[32];
    std::snprintf(limit, sizeof limit, "%g", watchdog_->limit_s());
    throw CallTimeout(describe(instance, what) + " did not return within " + limit + " s, the call time limit");
  }
  return status;
}

Master::Master(const MultiModel& mm, const CoSimConfig& config, const MasterOptions& options)
    : options_(options), config_(config), time_s_(config.start_s) {
  // The engine's steps: after a step at t the next is taken while t + h <= end (t by addition).
  for (double t = config.start_s; t + config.step_s <= config.end_s; t += config.step_s) ++total_steps_;
  watchdog_ = std::make_unique<CallWatchdog>(
      options.call_limit_s, [this](const CallWatchdog::Call& c) { return describe(c.instance, c.what); });
  std::map<std::string, FmuLibrary*> library_of;
  for (const auto& [key, file] : mm.fmus) {
    libraries_.push_back(std::make_unique<FmuLibrary>(file));
    watchdog_->remove_if_abandoned(libraries_.back()->folder());
    library_of[key] = libraries_.back().get();
  }
  std::map<std::string, std::size_t> index_of;   // "{FMU}.instance"
  std::map<const FmuLibrary*, int> instances_of;
  for (const auto& [key, name] : mm.instances) {
    auto in = std::make_unique<Instance>();
    in->fmu_key = key;
    in->name = name;
    in->label = key + "." + name;
    in->library = library_of.at(key);
    // A model with global state: every instance after the first gets a copy of the library.
    const bool own_copy = in->library->description().can_be_instantiated_only_once_per_process &&
                          instances_of[in->library]++ > 0;
    in->api = &in->library->api(own_copy ? in->library->load_copy() : 0);
    index_of[in->label] = instances_.size();
    instances_.push_back(std::move(in));
  }
  connect(mm, index_of);
  const auto variable = [&](const PortName& p, const std::string& where) -> const ModelVariable* {
    const std::size_t k = index_of.at(p.fmu + "." + p.instance);
    const ModelVariable* v = instances_[k]->library->description().find(p.variable);
    if (!v)
      throw InputError(mm.file + ": " + where,
                       p.fmu + " (" + instances_[k]->library->path() + ") has no variable " + p.variable);
    return v;
  };
  for (const Parameter& p : mm.parameters) {
    const ModelVariable* v = variable(p.port, p.where);
    const std::string where = mm.file + ": " + p.where;
    if (v->causality != "parameter" && v->causality != "input")
      throw InputError(where, p.port.variable + " is " + v->causality + ", not a parameter or an input");
    if (v->type == VarType::string && !p.is_text) throw InputError(where, p.port.variable + " is a String: expected a string");
    if (v->type != VarType::string && p.is_text)
      throw InputError(where, p.port.variable + " is " + to_string(v->type) + ": expected a number");
    if ((v->type == VarType::integer || v->type == VarType::boolean) && !p.integral)
      throw InputError(where, p.port.variable + " is " + to_string(v->type) + ": expected an integer");
  }
  record(mm, config, index_of);
  // Instantiate, start values, initialisation; on a failure, every instance made so far is freed
  // before the libraries close (the destructor does not run for a constructor that throws).
  try {
    start(mm);
  } catch (...) {
    release();
    throw;
  }
}

void Master::connect(const MultiModel& mm, const std::map<std::string, std::size_t>& index_of) {
  const auto variable = [&](const PortName& p, const std::string& where) -> std::pair<std::size_t, const ModelVariable*> {
    const std::size_t k = index_of.at(p.fmu + "." + p.instance);   // every instance named is one
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
  // The step's arrays: every instance's slices back to back, in stepping order.
  const auto slice = [](std::vector<uint32_t>& all, const std::vector<fmi2ValueReference>& mine) {
    const Slice s{static_cast<uint32_t>(all.size()), static_cast<uint32_t>(mine.size())};
    all.insert(all.end(), mine.begin(), mine.end());
    return s;
  };
  for (const auto& in : instances_) {
    Hot h;
    h.api = in->api;
    h.src_real = slice(src_real_vr_, in->source_real_vr);
    h.src_int = slice(src_int_vr_, in->source_int_vr);
    h.tgt_real = slice(tgt_real_vr_, in->target_real_vr);
    h.tgt_int = slice(tgt_int_vr_, in->target_int_vr);
    hot_.push_back(h);
  }
  src_real_.resize(src_real_vr_.size());
  src_int_.resize(src_int_vr_.size());
  tgt_real_.resize(tgt_real_vr_.size());
  tgt_int_.resize(tgt_int_vr_.size());
  for (const Link& l : links_) {
    const Hot& src = hot_[l.from];
    const Hot& dst = hot_[l.to];
    const auto target = static_cast<uint32_t>(l.to);
    if (l.type == VarType::real)
      real_copies_.push_back({src.src_real.begin + static_cast<uint32_t>(l.from_slot),
                              dst.tgt_real.begin + static_cast<uint32_t>(l.to_slot), target});
    else
      int_copies_.push_back({src.src_int.begin + static_cast<uint32_t>(l.from_slot),
                             dst.tgt_int.begin + static_cast<uint32_t>(l.to_slot), target});
  }
  const auto by_target = [](const Copy& a, const Copy& b) { return a.to < b.to; };
  std::sort(real_copies_.begin(), real_copies_.end(), by_target);
  std::sort(int_copies_.begin(), int_copies_.end(), by_target);
}

void Master::record(const MultiModel& mm, const CoSimConfig& config, const std::map<std::string, std::size_t>& index_of) {
  std::map<std::string, Port> recorded;   // by name: sorted, once each
  for (const Connection& c : mm.connections) {
    const std::size_t k = index_of.at(c.from.fmu + "." + c.from.instance);
    const ModelVariable& v = *instances_[k]->library->description().find(c.from.variable);   // connect() checked it
    recorded.emplace(c.from.text(), Port{k, v.value_reference, v.type});
  }
  for (const LogVariable& lv : config.log_variables) {
    const auto at = index_of.find(lv.port.fmu + "." + lv.port.instance);
    if (at == index_of.end()) throw InputError(lv.where, "the multi-model has no instance " + lv.port.fmu + "." + lv.port.instance);
    const Instance& in = *instances_[at->second];
    const ModelVariable* v = in.library->description().find(lv.port.variable);
    if (!v) throw InputError(lv.where, lv.port.fmu + " (" + in.library->path() + ") has no variable " + lv.port.variable);
    if (v->causality != "output" && v->causality != "local")
      throw InputError(lv.where, lv.port.variable + " is " + v->causality + ": the engine logs outputs and locals only");
    recorded.emplace(lv.port.text(), Port{at->second, v->value_reference, v->type});
  }
  for (const auto& [name, p] : recorded) {
    recorded_names_.push_back(name);
    recorded_.push_back(p);
  }
}

void Master::start(const MultiModel& mm) {
  std::map<std::string, std::vector<const Parameter*>> given;   // by instance ("{FMU}.instance")
  for (const Parameter& p : mm.parameters) given[p.port.fmu + "." + p.port.instance].push_back(&p);
  for (std::size_t k = 0; k < instances_.size(); ++k) {
    Instance* in = instances_[k].get();
    const ModelDescription& md = in->library->description();
    call(k, "fmi2Instantiate", [&] {
      in->component = in->api->instantiate(in->label.c_str(), fmi2CoSimulation, md.guid.c_str(),
                                           in->library->resource_uri().c_str(), &in->callbacks, fmi2False, fmi2False);
      return fmi2OK;
    });
    hot_[k].component = in->component;
    if (!in->component)
      throw InputError(in->library->path() + ": instance " + in->label,
                       "fmi2Instantiate failed" + (in->sink.last.empty() ? std::string() : ": " + in->sink.last));
    const double start_s = config_.start_s, end_s = config_.end_s;
    check(call(k, "fmi2SetupExperiment",
               [&] { return in->api->setup_experiment(in->component, fmi2False, 0.0, start_s, fmi2True, end_s); }),
          *in, "fmi2SetupExperiment");
    write_start_values(k, mm, given[in->label]);
  }
  for (std::size_t k = 0; k < instances_.size(); ++k) {
    const Hot& h = hot_[k];
    check(call(k, "fmi2EnterInitializationMode", [&] { return h.api->enter_initialization_mode(h.component); }),
          *instances_[k], "fmi2EnterInitializationMode");
  }
  for (std::size_t k = 0; k < instances_.size(); ++k) {
    const Hot& h = hot_[k];
    check(call(k, "fmi2ExitInitializationMode", [&] { return h.api->exit_initialization_mode(h.component); }),
          *instances_[k], "fmi2ExitInitializationMode");
  }
  initialised_ = true;
  for (std::size_t k = 0; k < instances_.size(); ++k) fetch_outputs(k);
}

// The engine's start values: every parameter and input with a start value in the model
// description, or a value in the multi-model's parameters (which wins), written one by one in
// the description's order (one at a time, so a refusal names its variable).
void Master::write_start_values(std::size_t k, const MultiModel& mm, const std::vector<const Parameter*>& parameters) {
  Instance& in = *instances_[k];
  std::map<std::string, const Parameter*> given;
  for (const Parameter* p : parameters) given[p->port.variable] = p;
  for (const ModelVariable& v : in.library->description().variables) {
    if (v.causality != "parameter" && v.causality != "input") continue;
    const auto it = given.find(v.name);
    const Parameter* p = it == given.end() ? nullptr : it->second;
    if (!p && !v.has_start) continue;
    const fmi2ValueReference vr = v.value_reference;
    const double number = p ? p->value : v.start_number;
    int status = fmi2OK;
    switch (v.type) {
      case VarType::real: status = in.api->set_real(in.component, &vr, 1, &number); break;
      case VarType::integer: {
        const int x = static_cast<int>(number);
        status = in.api->set_integer(in.component, &vr, 1, &x);
        break;
      }
      case VarType::boolean: {
        const int x = number != 0 ? fmi2True : fmi2False;
        status = in.api->set_boolean(in.component, &vr, 1, &x);
        break;
      }
      case VarType::string: {
        const char* x = p ? p->text.c_str() : v.start_text.c_str();
        status = in.api->set_string(in.component, &vr, 1, &x);
        break;
      }
    }
    if (status != fmi2OK)
      fail(status, in,
           p ? "setting parameter " + v.name + " (" + mm.file + ": " + p->where + ")"
             : "setting the start value of " + v.name + " (modelDescription.xml:" + std::to_string(v.line) + ")");
  }
}

// Terminates (after initialisation, as the engine) and frees every instance, each call under the
// time limit. An instance a call of which was interrupted is not terminated, only freed (FMI
// allows fmi2FreeInstance in any state), and its library stays loaded: its code may still run
// (a thread it started). One whose free is interrupted too is left as it is.
void Master::release() {
  for (std::size_t k = 0; k < instances_.size(); ++k) {
    Instance& in = *instances_[k];
    if (in.component) {
      int status = fmi2OK;
      if (!in.stuck && initialised_) {
        const auto terminate = [&] { return in.api->terminate(in.component); };
        in.stuck = !watchdog_->run(CallWatchdog::Call{k, "fmi2Terminate"}, terminate, status);
      }
      const auto free_instance = [&] {
        in.api->free_instance(in.component);
        return fmi2OK;
      };
      if (!watchdog_->run(CallWatchdog::Call{k, "fmi2FreeInstance"}, free_instance, status)) in.stuck = true;
      in.component = nullptr;
    }
    if (in.stuck) in.library->keep_loaded();
  }
}

Master::~Master() { release(); }

void Master::fetch_outputs(std::size_t source) {
  const Hot& h = hot_[source];
  if (h.src_real.size)
    check(h.api->get_real(h.component, &src_real_vr_[h.src_real.begin], h.src_real.size, &src_real_[h.src_real.begin]),
          *instances_[source], "fmi2GetReal");
  if (h.src_int.size)
    check(h.api->get_integer(h.component, &src_int_vr_[h.src_int.begin], h.src_int.size, &src_int_[h.src_int.begin]),
          *instances_[source], "fmi2GetInteger");
}
// Sets the target's inputs from its sources' outputs as they are now, fetched one by one
// (Gauss-Seidel: a source stepped earlier in this step shows its new value).
void Master::set_inputs(std::size_t target) {
  const Hot& dst = hot_[target];
  for (const std::size_t li : instances_[target]->links_in) {
    const Link& l = links_[li];
    const Hot& src = hot_[l.from];
    if (l.type == VarType::real) {
      const uint32_t from = src.src_real.begin + static_cast<uint32_t>(l.from_slot);
      check(src.api->get_real(src.component, &src_real_vr_[from], 1, &src_real_[from]), *instances_[l.from],
            "fmi2GetReal");
      tgt_real_[dst.tgt_real.begin + l.to_slot] = src_real_[from];
    } else {
      const uint32_t from = src.src_int.begin + static_cast<uint32_t>(l.from_slot);
      check(src.api->get_integer(src.component, &src_int_vr_[from], 1, &src_int_[from]), *instances_[l.from],
            "fmi2GetInteger");
      tgt_int_[dst.tgt_int.begin + l.to_slot] = src_int_[from];
    }
  }
  push_inputs(target, false);
}

void Master::push_inputs(std::size_t target, bool only_changed) {
  Hot& h = hot_[target];
  if (h.tgt_real.size && (h.real_changed || !only_changed))
    check(h.api->set_real(h.component, &tgt_real_vr_[h.tgt_real.begin], h.tgt_real.size, &tgt_real_[h.tgt_real.begin]),
          *instances_[target], "fmi2SetReal");
  if (h.tgt_int.size && (h.int_changed || !only_changed))
    check(h.api->set_integer(h.component, &tgt_int_vr_[h.tgt_int.begin], h.tgt_int.size, &tgt_int_[h.tgt_int.begin]),
          *instances_[target], "fmi2SetInteger");
  h.real_changed = h.int_changed = false;
}

void Master::step() {
  const double t = time_s_;
  const double h = config_.step_s;
  const auto do_step = [&](std::size_t k) {
    const Hot& hot = hot_[k];
    const int status = call(k, "fmi2DoStep", [&] { return hot.api->do_step(hot.component, t, h, fmi2True); });
    if (status == fmi2OK) return;
    char when[64];
    std::snprintf(when, sizeof when, "fmi2DoStep at t = %.17g s", t);
    fail(status, *instances_[k], when);
  };
  if (options_.algorithm == Algorithm::jacobi) {
    // The source buffers hold every output as of t (fetched after each instance's last step, or
    // after initialisation): copied to the inputs first, so stepping one instance cannot change
    // another's inputs. Each instance is then set, stepped and read in one visit (its data stays
    // in the cache).
    for (const Copy& c : real_copies_) {
      if (std::bit_cast<uint64_t>(tgt_real_[c.to]) == std::bit_cast<uint64_t>(src_real_[c.from])) continue;
      tgt_real_[c.to] = src_real_[c.from];
      hot_[c.target].real_changed = true;
    }
    for (const Copy& c : int_copies_) {
      if (tgt_int_[c.to] == src_int_[c.from]) continue;
      tgt_int_[c.to] = src_int_[c.from];
      hot_[c.target].int_changed = true;
    }
    for (std::size_t k = 0; k < hot_.size(); ++k) {
      push_inputs(k, true);
      do_step(k);
      fetch_outputs(k);
    }
  } else {
    for (std::size_t k = 0; k < instances_.size(); ++k) {
      set_inputs(k);
      do_step(k);
    }
  }
  ++steps_;
  time_s_ = t + h;
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
  const Fmi2Functions& api = *in.api;
  if (p.type == VarType::real) {
    double x = 0;
    check(api.get_real(in.component, &p.value_reference, 1, &x), in, "fmi2GetReal");
    return x;
  }
  int x = 0;
  if (p.type == VarType::integer) check(api.get_integer(in.component, &p.value_reference, 1, &x), in, "fmi2GetInteger");
  else if (p.type == VarType::boolean) check(api.get_boolean(in.component, &p.value_reference, 1, &x), in, "fmi2GetBoolean");
  else throw InputError(in.label, "a String variable has no number: read it as text");
  return x;
}

std::string Master::text(const Port& p) const {
  const Instance& in = *instances_[p.instance];
  if (p.type != VarType::string) throw InputError(in.label, "not a String variable");
  fmi2String x = nullptr;
  check(in.api->get_string(in.component, &p.value_reference, 1, &x), in, "fmi2GetString");
  return x ? x : "";
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
