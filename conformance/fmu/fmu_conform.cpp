#include "conformance/fmu/fmu_conform.hpp"

#include <fmt/format.h>
#include <rapidcheck.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "conformance/common/campaign.hpp"
#include "conformance/common/child_process.hpp"
#include "conformance/fmu/component_conform.hpp"
#include "fmi/export/fmu_export.hpp"
#include "fmi/master/fmu_library.hpp"
#include "fmi/master/master.hpp"
#include "impl/io/atomic_file.hpp"
#include "impl/io/interrupt.hpp"
#include "model/exploration/exploration_model.hpp"
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

// The FMU files in their roles (absolute paths; empty: not given), and what the Environment declares.
struct Loop {
  std::string environment, controller, body;
  int robots = 0, obstacles = 0;
};

// Which file is which (by the variables each has: eP, servoLeft, robot_x) and the Environment's
// robot and obstacle counts, read in a child process: loading someone's library may crash.
Loop identify(const FmuConformOptions& o, const fs::path& scratch) {
  std::vector<std::string> files;
  for (const std::string& f : {o.environment, o.controller, o.body})
    if (!f.empty()) files.push_back(f);
  if (files.size() != 1 && files.size() != 3)
    throw InputError("--fmu", "give one Controller or Body FMU, or the Environment, Controller and Body (three --fmu FILE)");
  for (const std::string& f : files) {
    std::error_code ec;
    if (!fs::is_regular_file(f, ec)) throw InputError(f, "no such FMU file");
  }
  const ChildEnd end = run_in_child([&](CaseProgress&) {
    // The FMUs unpack under the scratch folder, which the parent removes whatever the child does.
    fs::create_directories(scratch);
    ::setenv("TMPDIR", scratch.c_str(), 1);
    Json out = Json::object();
    for (const std::string& f : files) {
      const fm::FmuLibrary lib(f);
      const fm::ModelDescription& md = lib.description();
      const std::string role = md.find("eP") ? "environment" : md.find("servoLeft") ? "controller"
                               : md.find("robot_x")           ? "body"
                                                              : "";
      if (role.empty())
        throw InputError(f, "not an Environment (eP), a Controller (servoLeft) or a Body (robot_x) FMU of system A");
      if (out.contains(role)) throw InputError(f, "a second " + role + " FMU (give one of each)");
      out[role] = fs::absolute(f).string();
      if (role == "environment") {
        int n = 0, m = 0;
        while (md.find("xDesired" + std::to_string(n + 1))) ++n;
        while (md.find("ox_" + std::to_string(m + 1))) ++m;
        out["robots"] = n;
        out["obstacles"] = m;
      }
    }
    return out.dump();
  }, ChildLimits{std::chrono::seconds(60)});
  if (!end.finished()) {
    // A thrown InputError's text is its message; anything else is the FMU's fault.
    if (end.how == ChildEnd::How::threw) throw InputError("--fmu", end.output);
    throw InputError("--fmu", "loading the FMUs: " + end.describe());
  }
  const Json j = json_io::parse_json_text(end.output, "the FMUs' description (from a child process)");
  Loop loop{j.value("environment", ""), j.value("controller", ""), j.value("body", ""), j.value("robots", 0),
            j.value("obstacles", 0)};
  if (files.size() == 1 && !loop.environment.empty())
    throw InputError(loop.environment, "an Environment FMU alone cannot be checked: give its Controller and Body FMUs too");
  if (!loop.environment.empty() && loop.robots < 1)
    throw InputError(loop.environment, "the Environment FMU has no robots (no xDesired1 output)");
  return loop;
}

// The cases: a scenario with the Environment's robot and obstacle counts, any map they fit on,
// every rule set (unless one is given) and parameters with their edge values; cosim mode, the
// model's controller and body.
rc::Gen<ex::Scenario> gen_case(const Loop& loop, const FmuConformOptions& o) {
  return rc::gen::exec([loop, o] {
    ex::Scenario s = ex::default_scenario();
    s.mode = ex::Mode::cosim;
    s.controller = o.controller_law;
    s.body.kind = o.body_kind;
    const int cells_needed = loop.robots + loop.obstacles + 1;
    int side = 2;
    while (side * side < cells_needed) ++side;
    s.map_size = *rc::gen::inRange(side, side + 9);
    const int all = s.map_size * s.map_size;
    auto cells = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(loop.robots + loop.obstacles),
                                                       rc::gen::inRange(0, all));
    // Distinct cells: a cell already taken moves on to the next free one (shrinks towards cell 0).
    std::vector<char> taken(static_cast<std::size_t>(all), 0);
    for (int& c : cells) {
      while (taken[static_cast<std::size_t>(c)]) c = (c + 1) % all;
      taken[static_cast<std::size_t>(c)] = 1;
    }
    s.obstacles.clear();
    s.robots.clear();
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const ex::CellIndex c{cells[k] / s.map_size, cells[k] % s.map_size};
      if (static_cast<int>(k) < loop.obstacles) s.obstacles.push_back(c);
      else s.robots.push_back(ex::centre_of(c, s.cell_size));
    }
    s.rule = o.rule ? *o.rule : *rc::gen::element(ex::RuleSet::thesis, ex::RuleSet::deterministic, ex::RuleSet::stochastic);
    s.seed = *rc::gen::inRange<uint64_t>(0, 1000);
    s.params.s_range = *rc::gen::inRange(1, 4);
    s.params.a1 = *rc::gen::element(0.5, 1.0, 2.5);
    s.params.a2 = *rc::gen::element(0.5, 1.0, 4.0);
    s.params.epsilon = *rc::gen::element(0.0, 0.1, 1.0);
    s.params.max_ph = *rc::gen::element(2.0, 0.5, 10.0);
    s.params.ertu = *rc::gen::element(0.002, 0.05, 0.5);
    s.params.eta = *rc::gen::element(0.9, 0.5);
    s.params.phi = *rc::gen::element(1.0, 2.0, 0.0);
    s.params.lambda = *rc::gen::element(1.0, 0.0, 2.0);
    s.params.step_size = *rc::gen::element(0.1, 0.05, 0.2);
    s.max_steps = *rc::gen::inRange<int64_t>(1, o.max_steps + 1);
    return s;
  });
}

struct Prefixes {
  std::string environment;
  std::vector<std::string> controller, body;
};

Prefixes prefixes(FmuInterface i, std::size_t robots) {
  Prefixes p;
  p.environment = i == FmuInterface::thesis ? "{Environment}.EnvironmentInstance." : "{Environment}.environment.";
  for (std::size_t r = 0; r < robots; ++r) {
    const std::string k = std::to_string(r + 1);
    p.controller.push_back(i == FmuInterface::thesis ? "{Controller}.ControllerInstance" + k + "." : "{Controller}.controller" + k + ".");
    p.body.push_back(i == FmuInterface::thesis ? "{Robot" + k + "}.Robot" + k + "Instance." : "{Body}.body" + k + ".");
  }
  return p;
}

// The case as an INTO-CPS multi-model and configuration naming the loop's files, and its scenario.
void write_case(const ex::Scenario& s, const Loop& loop, FmuInterface i, const fs::path& dir, int64_t steps) {
  fs::create_directories(dir);
  const fmi::ModelFmus files{loop.environment, loop.controller, loop.body};
  io::write_file_atomically((dir / "multimodel.json").string(),
                            i == FmuInterface::thesis ? fmi::thesis_multimodel(s, files, true)
                                                      : fmi::intocps_multimodel(s, fmi::Handshake::flag, files, true));
  double end = 0.0;
  for (int64_t k = 0; k < steps; ++k) end = end + s.params.step_size;
  io::write_file_atomically((dir / "coe.json").string(), fmi::intocps_config(s.params.step_size, end));
  io::write_file_atomically((dir / "scenario.json").string(), json_io::to_json(s).dump(2) + "\n");
}

// One case in this (child) process: the master over the FMUs and the model, step by step; the
// first difference, or nothing.
std::optional<FmuDivergence> lockstep(const ex::Scenario& s, const fs::path& dir, const FmuConformOptions& o,
                                      CaseProgress& progress) {
  progress.at(0, CaseProgress::Side::impl);
  fm::Master master(fm::read_multimodel((dir / "multimodel.json").string()),
                    fm::read_config((dir / "coe.json").string()), fm::Algorithm::jacobi);
  model::exploration::ExplorationModel model(s);
  const Prefixes p = prefixes(o.interface, s.robots.size());
  struct Compared {
    std::string name;
    fm::Master::Port port;
  };
  std::vector<Compared> ports;
  const auto add = [&](const std::string& name) { ports.push_back({name, master.port(name)}); };
  for (std::size_t r = 0; r < s.robots.size(); ++r) {
    for (const char* v : {"robot_x", "robot_y", "robot_theta"}) add(p.body[r] + v);
    for (const char* v : {"servoLeft", "servoRight", "onDestinationOutput"}) add(p.controller[r] + v);
    add(p.environment + "xDesired" + std::to_string(r + 1));
    add(p.environment + "yDesired" + std::to_string(r + 1));
  }
  for (const char* v : {"onDestinationOutput", "eP", "sTime"}) add(p.environment + v);
  while (!master.done() && !model.done()) {
    const int64_t step = master.steps() + 1;
    progress.at(step, CaseProgress::Side::impl);
    master.step();
    progress.at(step, CaseProgress::Side::model);
    model.step();
    const ex::StepRecord rec = model.record();
    std::size_t k = 0;
    const auto check = [&](double expected) -> std::optional<FmuDivergence> {
      const Compared& c = ports[k++];
      const double got = master.value(c.port);
      if (o.tolerance.accepts(expected, got)) return std::nullopt;
      return FmuDivergence{step, c.name, expected, got, ""};
    };
    for (const ex::RobotRecord& r : rec.robots) {
      for (const double v : {r.body.x_m, r.body.y_m, r.body.theta_rad, r.controller.servo_left, r.controller.servo_right,
                             static_cast<double>(r.controller.on_destination_output), r.waypoint[0], r.waypoint[1]})
        if (auto d = check(v)) return d;
    }
    for (const double v : {static_cast<double>(rec.handshake.on_destination_output), rec.eP, rec.sTime})
      if (auto d = check(v)) return d;
  }
  return std::nullopt;
}

std::string outcome_text(const std::optional<FmuDivergence>& d) {
  if (!d) return "agree";
  Json j;
  j["step"] = d->step;
  j["variable"] = d->variable;
  j["model"] = std::bit_cast<uint64_t>(d->model);   // bits: NaN and -0.0 survive the pipe
  j["fmu"] = std::bit_cast<uint64_t>(d->fmu);
  return j.dump();
}

std::optional<FmuDivergence> read_outcome(const std::string& text) {
  if (text == "agree") return std::nullopt;
  const Json j = json_io::parse_json_text(text, "a case's outcome (from a child process)");
  return FmuDivergence{j["step"].get<int64_t>(), j["variable"].get<std::string>(),
                       std::bit_cast<double>(j["model"].get<uint64_t>()), std::bit_cast<double>(j["fmu"].get<uint64_t>()), ""};
}

std::optional<FmuDivergence> run_case(const ex::Scenario& s, const Loop& loop, const fs::path& dir,
                                      const FmuConformOptions& o, bool* hung) {
  write_case(s, loop, o.interface, dir, s.max_steps);
  const ChildEnd end = run_in_child(
      [&](CaseProgress& p) {
        // The master unpacks the FMUs under the case's folder: a child that crashes or is killed
        // leaves them there, and the parent removes the folder.
        ::setenv("TMPDIR", dir.c_str(), 1);
        return outcome_text(lockstep(s, dir, o, p));
      },
      ChildLimits{o.quiet_limit});
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.path().filename().string().rfind("swarmcheck-fmu-", 0) == 0) fs::remove_all(e.path(), ec);
  *hung = end.how == ChildEnd::How::hung;
  if (end.finished()) return read_outcome(end.output);
  FmuDivergence d;
  d.step = std::max<int64_t>(end.step, 0);
  d.abnormal_end = end.describe();
  return d;
}

// A temporary folder for the cases' files, removed whatever happens (Ctrl-C included).
struct CaseFolder {
  fs::path dir = fs::temp_directory_path() / ("swarmcheck-conform-fmu-" + std::to_string(::getpid()));
  int slot = -1;
  CaseFolder() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    slot = impl::io::register_temp_folder(dir.c_str());
  }
  ~CaseFolder() {
    std::error_code ec;
    fs::remove_all(dir, ec);
    impl::io::release_temp_file(slot);
  }
  CaseFolder(const CaseFolder&) = delete;
  CaseFolder& operator=(const CaseFolder&) = delete;
};

void write_counterexample(const FmuCounterexample& cx, const Loop& loop, const FmuConformOptions& o) {
  const fs::path dir(cx.folder);
  // The whole case up to the step that differs, so that a replay ends on it.
  write_case(cx.minimal, loop, o.interface, dir, std::max<int64_t>(cx.divergence.step, 1));
  Json d;
  d["step"] = cx.divergence.step;
  if (cx.divergence.abnormal_end.empty()) {
    d["variable"] = cx.divergence.variable;
    d["model"] = fmt::format("{:.17g}", cx.divergence.model);
    d["fmu"] = fmt::format("{:.17g}", cx.divergence.fmu);
  } else {
    d["abnormal_end"] = cx.divergence.abnormal_end;
  }
  d["tolerance"] = o.tolerance.bits() ? Json("bits") : Json({{"absolute", o.tolerance.absolute}, {"relative", o.tolerance.relative}});
  d["seed"] = o.seed;
  d["shrinks"] = cx.shrinks;
  io::write_file_atomically((dir / "divergence.json").string(), d.dump(2) + "\n");
  const std::string readme = fmt::format(
      "A minimal case on which the FMUs differ from swarmcheck's model: {}\n\n"
      "Replay it in swarmcheck's master (or any INTO-CPS-style master: multimodel.json names the FMU files):\n"
      "  swarmcheck cosim {}/multimodel.json --config {}/coe.json -o outputs.csv\n"
      "The model's run of the same case (the library's `run` is the model bit for bit):\n"
      "  swarmcheck run {}/scenario.json --json\n",
      cx.divergence.describe(), cx.folder, cx.folder, cx.folder);
  io::write_file_atomically((dir / "README.txt").string(), readme);
}

}  // namespace

bool Tolerance::accepts(double model, double fmu) const {
  if (bits()) return std::bit_cast<uint64_t>(model) == std::bit_cast<uint64_t>(fmu);
  if (std::isnan(model) || std::isnan(fmu)) return std::isnan(model) && std::isnan(fmu);
  return std::fabs(fmu - model) <= absolute + relative * std::fabs(model);
}

std::string FmuDivergence::describe() const {
  if (!abnormal_end.empty()) return abnormal_end;
  return fmt::format("step {}: {} model={:.17g} fmu={:.17g}", step, variable, model, fmu);
}

FmuConformReport run_fmu_conform(const FmuConformOptions& o) {
  if (o.cases < 1) throw InputError("--cases", "expected an integer >= 1");
  if (o.max_steps < 1) throw InputError("--max-steps", "expected an integer >= 1");
  if (o.tolerance.absolute < 0 || o.tolerance.relative < 0 || std::isnan(o.tolerance.absolute) ||
      std::isnan(o.tolerance.relative))
    throw InputError("--tolerance", "expected numbers >= 0");
  const CaseFolder work;
  const Loop loop = identify(o, work.dir / "identify");
  if (loop.environment.empty()) {   // one Controller or Body FMU alone
    const fs::path scratch = work.dir / "component";
    fs::create_directories(scratch);
    return loop.body.empty() ? run_component_conform(o, loop.controller, ComponentRole::controller, scratch.string())
                             : run_component_conform(o, loop.body, ComponentRole::body, scratch.string());
  }
  FmuConformReport report;
  report.robots = loop.robots;
  report.obstacles = loop.obstacles;
  std::optional<std::pair<ex::Scenario, FmuDivergence>> last_failure;
  int case_number = 0;
  const auto property = [&](CaseBudget& budget) {
    const ex::Scenario s = *gen_case(loop, o);
    try {
      ex::validate(s);
    } catch (const InputError&) {
      RC_DISCARD("not a valid scenario");
    }
    bool hung = false;
    const auto d = run_case(s, loop, work.dir / ("case-" + std::to_string(case_number++)), o, &hung);
    if (hung) budget.hung();
    if (d) last_failure.emplace(s, *d);
    RC_ASSERT(!d.has_value());
  };
  const CampaignRun run = run_campaign("fmu: the FMUs equal the model", o.seed, o.cases, property, o.on_case, ShrinkBudget{});
  report.cases_run = run.cases_run;
  if (!last_failure) return report;
  FmuCounterexample cx;
  cx.minimal = last_failure->first;
  cx.divergence = last_failure->second;
  cx.shrinks = run.shrinks;
  cx.folder = (fs::path(o.out_dir) / ("fmu-counterexample-seed" + std::to_string(o.seed))).string();
  std::error_code ec;
  fs::create_directories(cx.folder, ec);
  if (ec) throw InputError(o.out_dir, "cannot create the output folder: " + ec.message());
  write_counterexample(cx, loop, o);
  report.counterexample = cx;
  return report;
}

}  // namespace swarmcheck::conformance::fmu
