#include "conformance/fmu/component_conform.hpp"

#include <fmt/format.h>
#include <rapidcheck.h>
#include <stdlib.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "conformance/common/campaign.hpp"
#include "conformance/common/child_process.hpp"
#include "fmi/master/fmu_library.hpp"
#include "impl/io/atomic_file.hpp"
#include "spec/exploration/robot.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::conformance::fmu {
namespace {

namespace ex = swarmcheck::exploration;
namespace fm = swarmcheck::fmi::master;
namespace fs = std::filesystem;
using json_io::Json;

struct ControllerStepInputs {
  double x, y, phi, x_desired, y_desired;
  int32_t told;   // the Environment's onDestinationOutput
};

struct ComponentCase {
  ex::Scenario s;                                  // step, controller and body kinds, body parameters
  ex::Point_m start{0.0, 0.0};                     // a Body's start
  std::vector<std::array<double, 2>> servos;       // a Body's inputs, per step
  std::vector<ControllerStepInputs> controller;    // a Controller's inputs, per step
  std::size_t steps() const { return servos.empty() ? controller.size() : servos.size(); }
};

rc::Gen<double> servo_value() {
  return rc::gen::oneOf(rc::gen::element(0.0, 1.0, -1.0, 0.5, -0.5, 1.5, -2.0, 1e-9, -0.0),
                        rc::gen::map(rc::gen::inRange(-120, 121), [](int k) { return k / 100.0; }));
}

rc::Gen<ComponentCase> gen_case(const FmuConformOptions& o, ComponentRole role) {
  return rc::gen::exec([o, role] {
    ComponentCase c;
    c.s = ex::default_scenario();
    c.s.mode = ex::Mode::cosim;
    c.s.controller = o.controller_law;
    c.s.body.kind = o.body_kind;
    c.s.params.step_size = *rc::gen::element(0.1, 0.05, 0.2, 0.5);
    const auto steps = static_cast<std::size_t>(*rc::gen::inRange<int64_t>(1, o.max_steps + 1));
    if (role == ComponentRole::body) {
      c.start = {*rc::gen::inRange(0, 1000) / 100.0, *rc::gen::inRange(0, 1000) / 100.0};
      if (o.body_kind == ex::BodyKind::intocps) c.s.body.intocps.initial_position[2] = *rc::gen::inRange(-314, 315) / 100.0;
      c.servos = *rc::gen::container<std::vector<std::array<double, 2>>>(
          steps, rc::gen::map(rc::gen::pair(servo_value(), servo_value()),
                              [](const std::pair<double, double>& p) { return std::array<double, 2>{p.first, p.second}; }));
    } else {
      // Around a waypoint: arrivals, the atan2 fix's deadband, headings past +-pi; now and then the
      // Environment's flag (new waypoints).
      const auto offset = rc::gen::oneOf(rc::gen::element(0.0, 0.01, -0.01, 0.04, -0.06, 0.2, -0.25),
                                         rc::gen::map(rc::gen::inRange(-300, 301), [](int k) { return k / 100.0; }));
      const double wx = *rc::gen::inRange(0, 10) + 0.5, wy = *rc::gen::inRange(0, 10) + 0.5;
      for (std::size_t k = 0; k < steps; ++k)
        c.controller.push_back({wx + *offset, wy + *offset, *rc::gen::inRange(-700, 701) / 100.0, wx, wy,
                                *rc::gen::element(0, 0, 0, 0, 0, 1)});
    }
    return c;
  });
}

// The FMU's variables by name, set and read whatever their type (Real, or Integer for swarmcheck's
// handshake ports).
class Driven {
 public:
  Driven(const fm::FmuLibrary& lib) : lib_(lib) {
    c_ = lib.api().instantiate("conformed", fmi2CoSimulation, lib.description().guid.c_str(), lib.resource_uri().c_str(),
                               &callbacks_, fmi2False, fmi2False);
    if (!c_) throw std::runtime_error("fmi2Instantiate returned NULL");
  }
  ~Driven() { lib_.api().free_instance(c_); }
  Driven(const Driven&) = delete;
  Driven& operator=(const Driven&) = delete;
  bool has(const std::string& name) const { return lib_.description().find(name) != nullptr; }
  void set(const std::string& name, double v) {
    const fm::ModelVariable& var = variable(name);
    const fmi2ValueReference vr = var.value_reference;
    int status = 0;
    if (var.type == fm::VarType::integer) {
      const fmi2Integer i = static_cast<fmi2Integer>(v);
      status = lib_.api().set_integer(c_, &vr, 1, &i);
    } else {
      status = lib_.api().set_real(c_, &vr, 1, &v);
    }
    check(status, "fmi2Set " + name);
  }
  double get(const std::string& name) {
    const fm::ModelVariable& var = variable(name);
    const fmi2ValueReference vr = var.value_reference;
    if (var.type == fm::VarType::integer) {
      fmi2Integer i = 0;
      check(lib_.api().get_integer(c_, &vr, 1, &i), "fmi2GetInteger " + name);
      return i;
    }
    double v = 0;
    check(lib_.api().get_real(c_, &vr, 1, &v), "fmi2GetReal " + name);
    return v;
  }
  void setup(double stop_s) { check(lib_.api().setup_experiment(c_, fmi2False, 0, 0.0, fmi2True, stop_s), "fmi2SetupExperiment"); }
  void initialise() {
    check(lib_.api().enter_initialization_mode(c_), "fmi2EnterInitializationMode");
    check(lib_.api().exit_initialization_mode(c_), "fmi2ExitInitializationMode");
  }
  void step(double t, double h) { check(lib_.api().do_step(c_, t, h, fmi2True), "fmi2DoStep"); }

 private:
  static void no_log(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...) {}
  const fm::ModelVariable& variable(const std::string& name) const {
    const fm::ModelVariable* v = lib_.description().find(name);
    if (!v) throw std::runtime_error("the FMU has no variable " + name);
    return *v;
  }
  static void check(int status, const std::string& call) {
    if (status != fmi2OK && status != fmi2Warning) throw std::runtime_error(call + " returned status " + std::to_string(status));
  }
  const fm::FmuLibrary& lib_;
  fmi2CallbackFunctions callbacks_{no_log, nullptr, nullptr, nullptr, nullptr};
  fmi2Component c_ = nullptr;
};

// The model's outputs after each step, with their FMU names.
struct Expected {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;   // per step
};

Expected model_run(const ComponentCase& c, ComponentRole role) {
  const ex::RobotConfig cfg = ex::make_robot_config(c.s);
  Expected e;
  if (role == ComponentRole::body) {
    e.names = {"robot_x", "robot_y", "robot_theta"};
    const bool intocps = c.s.body.kind == ex::BodyKind::intocps;
    if (intocps)
      for (const char* n : {"wheel_left_rotation", "wheel_right_rotation", "encoder_left_output", "encoder_right_output",
                            "total_energy_used"})
        e.names.emplace_back(n);
    ex::BodyMemory b = ex::initial_body(cfg, c.start);
    double t = 0.0;
    for (const auto& u : c.servos) {
      ex::body_advance(cfg, b, u[0], u[1], t);
      t = t + c.s.params.step_size;
      std::vector<double> row{b.pose.x_m, b.pose.y_m, b.pose.theta_rad};
      if (intocps) {
        const ex::IntocpsBodyOutputs& out = b.intocps->outputs;
        for (const double v : {out.wheel_left_rotation, out.wheel_right_rotation, out.encoder_left_output,
                               out.encoder_right_output, out.total_energy_used})
          row.push_back(v);
      }
      e.rows.push_back(row);
    }
    return e;
  }
  e.names = {"servoLeft", "servoRight", "onDestinationOutput"};
  ex::ControllerState st = ex::initial_controller_of(cfg);
  for (const ControllerStepInputs& in : c.controller) {
    st = ex::controller_step(cfg, st, ex::ControllerInputs{{in.x, in.y, in.phi}, {in.x_desired, in.y_desired}, in.told,
                                                           c.s.params.step_size});
    e.rows.push_back({st.servo_left, st.servo_right, static_cast<double>(st.on_destination_output)});
  }
  return e;
}

// The FMU's parameters for the case: every one the model's component reads.
void set_parameters(Driven& d, const ComponentCase& c, ComponentRole role) {
  if (role == ComponentRole::controller) {
    const bool thesis = c.s.controller == ex::ControllerKind::thesis;
    d.set("k_beta", thesis ? ex::ThesisControllerParams{}.k_beta : ex::RobotParams{}.k_beta);
    d.set("k_v", thesis ? ex::ThesisControllerParams{}.k_v : ex::RobotParams{}.k_v);
    if (d.has("handshake")) d.set("handshake", 0);
    return;
  }
  if (c.s.body.kind == ex::BodyKind::intocps) {
    for (const ex::IntocpsBodyParameter& p : ex::intocps_body_parameters())
      d.set(std::string(p.name), ex::intocps_parameter_value(c.s.body.intocps, p));
    d.set("initial_position[0]", c.start[0]);
    d.set("initial_position[1]", c.start[1]);
    return;
  }
  const ex::RobotParams rp;
  d.set("x0", c.start[0]);
  d.set("y0", c.start[1]);
  d.set("theta0", 0.0);
  d.set("wheel_radius", rp.wheel_radius_m);
  d.set("motor_gain", rp.motor_gain_rad_per_s);
  d.set("half_axle", rp.half_axle_m);
}

// In the child: the FMU through the case, compared step by step with `expected`.
std::optional<FmuDivergence> drive(const std::string& fmu, const ComponentCase& c, ComponentRole role,
                                   const Expected& expected, const Tolerance& tolerance, CaseProgress& p) {
  p.at(0, CaseProgress::Side::impl);
  const fm::FmuLibrary lib(fmu);
  Driven d(lib);
  double end = 0.0;
  for (std::size_t k = 0; k < c.steps(); ++k) end = end + c.s.params.step_size;
  d.setup(end + 1.0);
  set_parameters(d, c, role);
  d.initialise();
  double t = 0.0;
  for (std::size_t k = 0; k < c.steps(); ++k) {
    p.at(static_cast<int64_t>(k + 1), CaseProgress::Side::impl);
    if (role == ComponentRole::body) {
      d.set("servo_left_input", c.servos[k][0]);
      d.set("servo_right_input", c.servos[k][1]);
    } else {
      const ControllerStepInputs& in = c.controller[k];
      d.set("x", in.x), d.set("y", in.y), d.set("phi", in.phi);
      d.set("xDesired", in.x_desired), d.set("yDesired", in.y_desired);
      d.set("onDestinationInput", in.told);
    }
    d.step(t, c.s.params.step_size);
    t = t + c.s.params.step_size;
    for (std::size_t v = 0; v < expected.names.size(); ++v) {
      const double got = d.get(expected.names[v]);
      if (!tolerance.accepts(expected.rows[k][v], got))
        return FmuDivergence{static_cast<int64_t>(k + 1), expected.names[v], expected.rows[k][v], got, ""};
    }
  }
  return std::nullopt;
}

Json case_json(const ComponentCase& c, ComponentRole role) {
  Json j;
  j["component"] = role == ComponentRole::body ? "body" : "controller";
  j["step_size"] = c.s.params.step_size;
  if (role == ComponentRole::body) {
    j["body"] = json_io::to_json(c.s.body);
    j["start"] = {c.start[0], c.start[1]};
    j["servos"] = c.servos;
  } else {
    j["controller"] = json_io::enum_to_string(c.s.controller);
    Json steps = Json::array();
    for (const ControllerStepInputs& in : c.controller)
      steps.push_back({{"x", in.x}, {"y", in.y}, {"phi", in.phi}, {"xDesired", in.x_desired}, {"yDesired", in.y_desired},
                       {"onDestinationInput", in.told}});
    j["inputs"] = steps;
  }
  return j;
}

void write_counterexample(const std::string& folder, const ComponentCase& c, ComponentRole role, const FmuDivergence& d,
                          const FmuConformOptions& o, int shrinks) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw InputError(folder, "cannot create the output folder: " + ec.message());
  io::write_file_atomically(folder + "/case.json", case_json(c, role).dump(2) + "\n");
  Json dj;
  dj["step"] = d.step;
  if (d.abnormal_end.empty()) {
    dj["variable"] = d.variable;
    dj["model"] = fmt::format("{:.17g}", d.model);
    dj["fmu"] = fmt::format("{:.17g}", d.fmu);
  } else {
    dj["abnormal_end"] = d.abnormal_end;
  }
  dj["tolerance"] = o.tolerance.bits() ? Json("bits") : Json({{"absolute", o.tolerance.absolute}, {"relative", o.tolerance.relative}});
  dj["seed"] = o.seed;
  dj["shrinks"] = shrinks;
  io::write_file_atomically(folder + "/divergence.json", dj.dump(2) + "\n");
  // The model's outputs at every step, %.17g, for driving the FMU with case.json's inputs elsewhere.
  const Expected e = model_run(c, role);
  std::string csv = "step,time";
  for (const std::string& n : e.names) csv += "," + n;
  csv += "\n";
  double t = 0.0;
  for (std::size_t k = 0; k < e.rows.size(); ++k) {
    t = t + c.s.params.step_size;
    csv += fmt::format("{},{:.17g}", k + 1, t);
    for (const double v : e.rows[k]) csv += fmt::format(",{:.17g}", v);
    csv += "\n";
  }
  io::write_file_atomically(folder + "/expected.csv", csv);
}

}  // namespace

FmuConformReport run_component_conform(const FmuConformOptions& o, const std::string& fmu, ComponentRole role,
                                       const std::string& scratch) {
  FmuConformReport report;
  report.checked = role == ComponentRole::body ? "body" : "controller";
  std::optional<std::pair<ComponentCase, FmuDivergence>> last_failure;
  const auto property = [&](CaseBudget& budget) {
    const ComponentCase c = *gen_case(o, role);
    const Expected expected = model_run(c, role);   // the model in the parent: it is the oracle
    const ChildEnd end = run_in_child(
        [&](CaseProgress& p) {
          ::setenv("TMPDIR", scratch.c_str(), 1);   // unpacked under a folder the parent empties
          const auto d = drive(fmu, c, role, expected, o.tolerance, p);
          if (!d) return std::string("agree");
          Json j{{"step", d->step}, {"variable", d->variable}, {"model", std::bit_cast<uint64_t>(d->model)},
                 {"fmu", std::bit_cast<uint64_t>(d->fmu)}};
          return j.dump();
        },
        ChildLimits{o.quiet_limit});
    if (end.how == ChildEnd::How::hung) budget.hung();
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(scratch, ec)) fs::remove_all(e.path(), ec);   // a killed child's FMU
    std::optional<FmuDivergence> d;
    if (end.finished()) {
      if (end.output != "agree") {
        const Json j = json_io::parse_json_text(end.output, "a case's outcome (from a child process)");
        d = FmuDivergence{j["step"].get<int64_t>(), j["variable"].get<std::string>(),
                          std::bit_cast<double>(j["model"].get<uint64_t>()), std::bit_cast<double>(j["fmu"].get<uint64_t>()), ""};
      }
    } else {
      d = FmuDivergence{std::max<int64_t>(end.step, 0), "", 0.0, 0.0, end.describe()};
    }
    if (d) last_failure.emplace(c, *d);
    RC_ASSERT(!d.has_value());
  };
  const CampaignRun run = run_campaign("fmu: the component FMU equals the model", o.seed, o.cases, property, o.on_case,
                                       ShrinkBudget{});
  report.cases_run = run.cases_run;
  if (!last_failure) return report;
  FmuCounterexample cx;
  cx.minimal = last_failure->first.s;
  cx.divergence = last_failure->second;
  cx.shrinks = run.shrinks;
  cx.folder = (fs::path(o.out_dir) / ("fmu-counterexample-seed" + std::to_string(o.seed))).string();
  write_counterexample(cx.folder, last_failure->first, role, cx.divergence, o, cx.shrinks);
  report.counterexample = cx;
  return report;
}

}  // namespace swarmcheck::conformance::fmu
