#include "fmi/export/fmu_export.hpp"

#include <zip.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "fmi/fmu/model_description.hpp"
#include "impl/io/atomic_file.hpp"
#include "spec/exploration/controller_thesis.hpp"
#include "spec/exploration/neighbourhood.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "swarmcheck/exploration.hpp"

extern "C" const unsigned char swarmcheck_fmu_so_begin[];
extern "C" const unsigned char swarmcheck_fmu_so_end[];

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

// 2020-01-01T00:00:00Z: every entry's time, so the same export gives the same bytes.
constexpr time_t kEntryTime = 1577836800;

struct Entry {
  std::string name;
  std::string bytes;
};

std::string zip_bytes(const std::vector<Entry>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* memory = zip_source_buffer_create(nullptr, 0, 0, &error);
  if (!memory) throw std::runtime_error("libzip: cannot create an archive in memory");
  zip_source_keep(memory);
  const auto free_memory = std::unique_ptr<zip_source_t, void (*)(zip_source_t*)>(memory, zip_source_free);
  zip_t* archive = zip_open_from_source(memory, ZIP_TRUNCATE, &error);
  if (!archive) throw std::runtime_error(std::string("libzip: ") + zip_error_strerror(&error));
  for (const Entry& e : entries) {
    zip_source_t* data = zip_source_buffer(archive, e.bytes.data(), e.bytes.size(), 0);
    const zip_int64_t index = data ? zip_file_add(archive, e.name.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (data) zip_source_free(data);
      const std::string why = zip_strerror(archive);
      zip_discard(archive);
      throw std::runtime_error("libzip: cannot add " + e.name + ": " + why);
    }
    zip_file_set_mtime(archive, static_cast<zip_uint64_t>(index), kEntryTime, 0);
    // Stored as a Unix file, -rw-r--r-- (libzip's default leaves the mode to the unpacking tool,
    // which on Linux gives 0666 less its umask, or 0666 as is).
    zip_file_set_external_attributes(archive, static_cast<zip_uint64_t>(index), 0, ZIP_OPSYS_UNIX,
                                     static_cast<zip_uint32_t>(0100644) << 16);
  }
  if (zip_close(archive) != 0) {
    const std::string why = zip_strerror(archive);
    zip_discard(archive);
    throw std::runtime_error("libzip: cannot write the archive: " + why);
  }
  zip_stat_t st;
  if (zip_source_stat(memory, &st) != 0 || zip_source_open(memory) != 0)
    throw std::runtime_error("libzip: cannot read the archive back");
  std::string out(static_cast<std::size_t>(st.size), '\0');
  const zip_int64_t got = zip_source_read(memory, out.data(), st.size);
  zip_source_close(memory);
  if (got != static_cast<zip_int64_t>(st.size)) throw std::runtime_error("libzip: short read of the archive");
  return out;
}

std::string library_bytes() {
  return std::string(reinterpret_cast<const char*>(swarmcheck_fmu_so_begin),
                     static_cast<std::size_t>(swarmcheck_fmu_so_end - swarmcheck_fmu_so_begin));
}

// The end of a run of s: the library's completion step for this scenario (the same system), else
// max_steps, as the engine's clock reads it after that many steps: the repeated sum of step_size
// (the engine steps while t + h <= endTime, t by repeated addition, so this end gives exactly
// that many steps; k * h may fall below the sum and lose the last step).
double completion_end_time(const ex::Scenario& s) {
  ex::Scenario as_cosim = s;
  as_cosim.mode = ex::Mode::cosim;
  Exploration run(as_cosim, ExplorationOptions{});
  while (!run.done()) run.step();
  const int64_t steps = run.completion_step().value_or(s.max_steps);
  double t = 0.0;
  for (int64_t k = 0; k < steps; ++k) t = t + s.params.step_size;
  return t;
}

}  // namespace

ex::Scenario scenario_with_robots(const ex::Scenario& s, int32_t n) {
  if (n == static_cast<int32_t>(s.robots.size())) return s;
  const int64_t free = ex::free_cell_count(s);
  if (n < 1 || n > free)
    throw InputError("--robots", "expected 1.." + std::to_string(free) + " (the scenario's free cells), got " +
                                     std::to_string(n));
  std::vector<char> blocked(static_cast<std::size_t>(s.map_size) * static_cast<std::size_t>(s.map_size), 0);
  for (const ex::CellIndex& c : s.obstacles)
    blocked[static_cast<std::size_t>(c[0]) * static_cast<std::size_t>(s.map_size) + static_cast<std::size_t>(c[1])] = 1;
  ex::Scenario out = s;
  out.robots.clear();
  int64_t k = 0, seen = 0;
  for (int32_t i = 0; i < s.map_size && k < n; ++i)
    for (int32_t j = 0; j < s.map_size && k < n; ++j) {
      if (blocked[static_cast<std::size_t>(i) * static_cast<std::size_t>(s.map_size) + static_cast<std::size_t>(j)]) continue;
      if (seen == k * free / n) {
        out.robots.push_back(ex::centre_of(ex::CellIndex{i, j}, s.cell_size));
        ++k;
      }
      ++seen;
    }
  ex::validate(out);
  return out;
}

ex::Scenario thesis_interface_scenario() {
  ex::Scenario s = ex::default_scenario();
  s.map_size = 10;
  s.robots = {{0.5, 0.5}, {9.5, 0.5}, {9.5, 9.5}, {0.5, 9.5}};
  s.obstacles = {{3, 1}, {4, 1}, {2, 9}, {5, 4}, {5, 5}, {7, 8}, {8, 8}, {8, 9}};
  s.params.a1 = 0.5;
  s.params.a2 = 0.5;
  s.params.ertu = 0.002;
  s.params.eta = 0.9;
  s.params.lambda = 1;
  s.params.max_ph = 2;
  s.params.phi = 1;
  s.params.s_range = 1;
  s.params.step_size = 0.1;
  s.rule = ex::RuleSet::thesis;
  ex::validate(s);
  return s;
}

FmuSetup fmu_setup(Kind kind, const ex::Scenario& s, Interface interface) {
  if (s.seed > static_cast<uint64_t>(INT32_MAX))
    throw InputError("seed", "the FMU's seed parameter is an FMI Integer: expected at most 2147483647, got " +
                                 std::to_string(s.seed));
  FmuSetup setup;
  setup.kind = kind;
  setup.interface = interface;
  setup.scenario = s;
  setup.scenario.mode = ex::Mode::cosim;
  if (interface == Interface::thesis) {
    // The thesis's Controller and Body: its published UController's law and the 20-sim body.
    setup.scenario.controller = ex::ControllerKind::thesis;
    setup.scenario.body.kind = ex::BodyKind::intocps;
  }
  if (kind == Kind::environment) {
    constexpr int32_t kThesisObstacleSlots = 10;   // ox_1..ox_10 in the thesis's Environment
    setup.robots = static_cast<int32_t>(s.robots.size());
    setup.obstacles = static_cast<int32_t>(s.obstacles.size());
    if (interface == Interface::thesis) setup.obstacles = std::max(setup.obstacles, kThesisObstacleSlots);
  }
  return setup;
}

std::string fmu_archive(const FmuSetup& setup) { return fmu_archive(setup, library_bytes()); }

std::string fmu_archive(const FmuSetup& setup, const std::string& library) {
  const std::string id = model_identifier(setup.kind);
  return zip_bytes({{"modelDescription.xml", model_description_xml(setup, ex::kToolVersion)},
                    {"binaries/linux64/" + id + ".so", library},
                    {"resources/swarmcheck-fmu.json", setup_to_json(setup)}});
}

void write_fmu(const FmuSetup& setup, const std::string& path) { io::write_file_atomically(path, fmu_archive(setup)); }

namespace {

// Every parameter the scenario decides, for an Environment whose instance prefix is `env`: what
// conform --fmu writes so that FMUs of any start values run the case (swarmcheck's names; the
// thesis interface's Environment has them too, with nRobots and nObstacles).
void scenario_parameters(const ex::Scenario& s, const std::string& env, bool thesis, json_io::Json& parameters) {
  parameters[env + "mapSize"] = s.map_size;
  parameters[env + "cellSize"] = s.cell_size;
  parameters[env + "step_size"] = s.params.step_size;
  parameters[env + "s_range"] = s.params.s_range;
  parameters[env + "a1"] = s.params.a1;
  parameters[env + "a2"] = s.params.a2;
  parameters[env + "epsilon"] = s.params.epsilon;
  parameters[env + "ertu_perc"] = s.params.ertu;
  parameters[env + "eta"] = s.params.eta;
  parameters[env + "max_ph"] = s.params.max_ph;
  parameters[env + "phi"] = s.params.phi;
  parameters[env + "lambda"] = s.params.lambda;
  parameters[env + "rule"] = static_cast<int32_t>(s.rule);   // 0 thesis, 1 deterministic, 2 stochastic
  parameters[env + "seed"] = static_cast<int32_t>(s.seed);
  for (std::size_t r = 0; r < s.robots.size(); ++r) {
    parameters[env + "lx_" + std::to_string(r + 1)] = s.robots[r][0];
    parameters[env + "ly_" + std::to_string(r + 1)] = s.robots[r][1];
  }
  for (std::size_t k = 0; k < s.obstacles.size(); ++k) {
    parameters[env + "ox_" + std::to_string(k + 1)] = s.obstacles[k][0];
    parameters[env + "oy_" + std::to_string(k + 1)] = s.obstacles[k][1];
  }
  if (thesis) {
    parameters[env + "nRobots"] = static_cast<int32_t>(s.robots.size());
    parameters[env + "nObstacles"] = static_cast<int32_t>(s.obstacles.size());
  }
}

// A body instance's parameters: the kinematic body's, or every one of the 20-sim body's.
void body_parameters(const ex::Scenario& s, std::size_t r, const std::string& body, bool every, json_io::Json& parameters) {
  if (s.body.kind == ex::BodyKind::intocps) {
    parameters[body + "initial_position[0]"] = s.robots[r][0];
    parameters[body + "initial_position[1]"] = s.robots[r][1];
    for (const ex::IntocpsBodyParameter& d : ex::intocps_body_parameters())
      if (d.initial_position_index < 0 || d.initial_position_index == 2) {
        const double v = ex::intocps_parameter_value(s.body.intocps, d);
        if (every || v != ex::intocps_parameter_value(ex::IntocpsBodyParams{}, d)) parameters[body + std::string(d.name)] = v;
      }
    return;
  }
  parameters[body + "x0"] = s.robots[r][0];
  parameters[body + "y0"] = s.robots[r][1];
  if (every) {
    const ex::RobotParams rp;
    parameters[body + "theta0"] = 0.0;
    parameters[body + "wheel_radius"] = rp.wheel_radius_m;
    parameters[body + "motor_gain"] = rp.motor_gain_rad_per_s;
    parameters[body + "half_axle"] = rp.half_axle_m;
  }
}

// A controller instance's gains as the model's law has them.
void controller_parameters(const ex::Scenario& s, const std::string& ctrl, json_io::Json& parameters) {
  if (s.controller == ex::ControllerKind::thesis) {
    const ex::ThesisControllerParams tp;
    parameters[ctrl + "k_beta"] = tp.k_beta;
    parameters[ctrl + "k_v"] = tp.k_v;
  } else {
    const ex::RobotParams rp;
    parameters[ctrl + "k_beta"] = rp.k_beta;
    parameters[ctrl + "k_v"] = rp.k_v;
  }
}

}  // namespace

std::string intocps_multimodel(const ex::Scenario& s, Handshake handshake, const ModelFmus& files, bool every_parameter) {
  using json_io::Json;
  Json mm;
  // Gauss-Seidel steps instances in this order: the controllers and bodies, then the Environment.
  mm["fmus"] = Json::object({{"{Controller}", files.controller}, {"{Body}", files.body}, {"{Environment}", files.environment}});
  Json connections = Json::object();
  const std::string env = "{Environment}.environment.";
  Json on_destination = Json::array(), epoch = Json::array();
  const int32_t hs = handshake == Handshake::epoch ? 1 : 0;
  Json parameters = Json::object();
  parameters[env + "handshake"] = hs;
  for (std::size_t r = 0; r < s.robots.size(); ++r) {
    const std::string i = std::to_string(r + 1);
    const std::string ctrl = "{Controller}.controller" + i + ".";
    const std::string body = "{Body}.body" + i + ".";
    connections[env + "xDesired" + i] = Json::array({ctrl + "xDesired"});
    connections[env + "yDesired" + i] = Json::array({ctrl + "yDesired"});
    connections[ctrl + "onDestinationOutput"] = Json::array({env + "onDestination" + i + "Input"});
    connections[ctrl + "epochAck"] = Json::array({env + "epochAck" + i});
    connections[ctrl + "servoLeft"] = Json::array({body + "servo_left_input"});
    connections[ctrl + "servoRight"] = Json::array({body + "servo_right_input"});
    connections[body + "robot_x"] = Json::array({ctrl + "x", env + "x_" + i});
    connections[body + "robot_y"] = Json::array({ctrl + "y", env + "y_" + i});
    connections[body + "robot_theta"] = Json::array({ctrl + "phi"});
    on_destination.push_back(ctrl + "onDestinationInput");
    epoch.push_back(ctrl + "epochInput");
    body_parameters(s, r, body, every_parameter, parameters);
    parameters[ctrl + "handshake"] = hs;
    if (every_parameter) controller_parameters(s, ctrl, parameters);
  }
  if (every_parameter) scenario_parameters(s, env, false, parameters);
  connections[env + "onDestinationOutput"] = on_destination;
  connections[env + "epoch"] = epoch;
  mm["connections"] = connections;
  mm["parameters"] = parameters;

  return mm.dump(2) + "\n";
}

std::string intocps_config(double step_s, double end_s) {
  json_io::Json coe;
  coe["startTime"] = 0.0;
  coe["endTime"] = end_s;
  coe["algorithm"] = json_io::Json::object({{"type", "fixed-step"}, {"size", step_s}});
  return coe.dump(2) + "\n";
}

void write_intocps(const ex::Scenario& s, Handshake handshake, const std::string& dir, std::optional<double> end_time_s) {
  if (handshake == Handshake::epoch && s.controller == ex::ControllerKind::thesis)
    throw InputError("--handshake", "the thesis controller has the flag handshake only (its published UController)");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir, "cannot create the folder: " + ec.message());
  const auto in = [&](const std::string& name) { return (std::filesystem::path(dir) / name).string(); };
  // Every output must be writable before any is written (a folder named coe.json refused after the
  // FMUs were replaced left a folder half old, half new).
  for (const char* name : {"Environment.fmu", "Controller.fmu", "Body.fmu", "coe.json", "multimodel.json"})
    io::check_output_path(in(name));
  // Each archive is whole or absent; the multi-model goes last, so a folder with it is complete.
  write_fmu(fmu_setup(Kind::environment, s), in("Environment.fmu"));
  write_fmu(fmu_setup(Kind::controller, s), in("Controller.fmu"));
  write_fmu(fmu_setup(Kind::body, s), in("Body.fmu"));

  const std::string mm = intocps_multimodel(s, handshake, {"Environment.fmu", "Controller.fmu", "Body.fmu"});
  if (!end_time_s) end_time_s = completion_end_time(s);
  io::write_file_atomically(in("coe.json"), intocps_config(s.params.step_size, *end_time_s));
  io::write_file_atomically(in("multimodel.json"), mm);
}

std::string thesis_multimodel(const ex::Scenario& s, const ModelFmus& files, bool every_parameter) {
  const std::size_t n = s.robots.size();
  using json_io::Json;
  Json mm;
  Json fmu_files = Json::object({{"{Environment}", files.environment}, {"{Controller}", files.controller}});
  for (std::size_t r = 0; r < n; ++r)
    fmu_files["{Robot" + std::to_string(r + 1) + "}"] = r < files.bodies.size() ? files.bodies[r] : files.body;
  mm["fmus"] = fmu_files;
  const std::string env = "{Environment}.EnvironmentInstance.";
  Json connections = Json::object(), parameters = Json::object();
  Json told = Json::array();
  for (std::size_t r = 0; r < n; ++r) {
    const std::string k = std::to_string(r + 1);
    const std::string ctrl = "{Controller}.ControllerInstance" + k + ".";
    const std::string robot = "{Robot" + k + "}.Robot" + k + "Instance.";
    connections[env + "xDesired" + k] = Json::array({ctrl + "xDesired"});
    connections[env + "yDesired" + k] = Json::array({ctrl + "yDesired"});
    connections[ctrl + "onDestinationOutput"] = Json::array({env + "onDestination" + k + "Input"});
    connections[ctrl + "servoLeft"] = Json::array({robot + "servo_left_input"});
    connections[ctrl + "servoRight"] = Json::array({robot + "servo_right_input"});
    connections[robot + "robot_x"] = Json::array({env + "x_" + k, ctrl + "x"});
    connections[robot + "robot_y"] = Json::array({env + "y_" + k, ctrl + "y"});
    connections[robot + "robot_theta"] = Json::array({ctrl + "phi"});
    told.push_back(ctrl + "onDestinationInput");
    parameters[env + "lx_" + k] = s.robots[r][0];
    parameters[env + "ly_" + k] = s.robots[r][1];
    body_parameters(s, r, robot, every_parameter, parameters);
    if (every_parameter) controller_parameters(s, ctrl, parameters);
  }
  connections[env + "onDestinationOutput"] = told;
  mm["connections"] = connections;
  parameters[env + "mapSize"] = s.map_size;
  parameters[env + "nRobots"] = static_cast<int32_t>(n);
  parameters[env + "nObstacles"] = static_cast<int32_t>(s.obstacles.size());
  for (std::size_t k = 0; k < s.obstacles.size(); ++k) {
    parameters[env + "ox_" + std::to_string(k + 1)] = s.obstacles[k][0];
    parameters[env + "oy_" + std::to_string(k + 1)] = s.obstacles[k][1];
  }
  if (every_parameter) scenario_parameters(s, env, true, parameters);
  mm["parameters"] = parameters;
  return mm.dump(2) + "\n";
}

ThesisProject write_intocps_thesis(const ex::Scenario& scenario, const std::string& dir, std::optional<double> end_time_s) {
  ex::Scenario s = scenario;
  s.mode = ex::Mode::cosim;
  s.controller = ex::ControllerKind::thesis;
  s.body.kind = ex::BodyKind::intocps;
  namespace fs = std::filesystem;
  const fs::path root(dir);
  ThesisProject p;
  p.multimodel = (root / "Multi-models" / "mm-new" / "mm.json").string();
  p.config = (root / "Multi-models" / "mm-new" / "co-sim" / "coe.json").string();
  const fs::path fmus = root / "FMUs";
  const std::size_t n = s.robots.size();
  std::vector<std::string> bodies;
  for (std::size_t r = 0; r < n; ++r) bodies.push_back("Body_Block" + std::to_string(r + 1) + ".fmu");
  std::vector<std::string> outputs{(fmus / "Environment.fmu").string(), (fmus / "UController.fmu").string()};
  for (const std::string& b : bodies) outputs.push_back((fmus / b).string());
  for (const auto& folder : {fmus, fs::path(p.multimodel).parent_path(), fs::path(p.config).parent_path()}) {
    std::error_code ec;
    fs::create_directories(folder, ec);
    if (ec) throw InputError(folder.string(), "cannot create the folder: " + ec.message());
  }
  for (const std::string& out : outputs) io::check_output_path(out);
  io::check_output_path(p.multimodel);
  io::check_output_path(p.config);
  if (!end_time_s) end_time_s = completion_end_time(s);
  // The FMUs (the four bodies are copies of one, as the thesis ships them), then the configuration,
  // then the multi-model last: a project with it is complete.
  write_fmu(fmu_setup(Kind::environment, s, Interface::thesis), outputs[0]);
  write_fmu(fmu_setup(Kind::controller, s, Interface::thesis), outputs[1]);
  const std::string body = fmu_archive(fmu_setup(Kind::body, s, Interface::thesis));
  for (std::size_t r = 0; r < n; ++r) io::write_file_atomically(outputs[2 + r], body);

  const std::string mm = thesis_multimodel(s, {"Environment.fmu", "UController.fmu", "", bodies});
  // The published coe.json's keys, with this run's end.
  json_io::Json coe;
  coe["startTime"] = 0;
  coe["endTime"] = *end_time_s;
  coe["multimodel_path"] = "Multi-models/mm-new/mm.json";
  coe["algorithm"] = json_io::Json::object({{"type", "fixed-step"}, {"size", s.params.step_size}});
  coe["liveGraphColumns"] = 1;
  coe["liveGraphVisibleRowCount"] = 1;
  coe["graphs"] = json_io::Json::array();
  coe["livestreamInterval"] = 0;
  coe["logVariables"] = json_io::Json::object();
  coe["visible"] = false;
  coe["loggingOn"] = false;
  coe["overrideLogLevel"] = nullptr;
  coe["enableAllLogCategoriesPerInstance"] = false;
  coe["postProcessingScript"] = "";
  coe["parallelSimulation"] = false;
  coe["stabalizationEnabled"] = false;
  coe["global_absolute_tolerance"] = 0;
  coe["global_relative_tolerance"] = 0.01;
  coe["simulationProgramDelay"] = true;
  io::write_file_atomically(p.config, coe.dump(2) + "\n");
  io::write_file_atomically(p.multimodel, mm);
  return p;
}

}  // namespace swarmcheck::fmi
