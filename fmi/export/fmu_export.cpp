#include "fmi/export/fmu_export.hpp"

#include <zip.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "fmi/fmu/model_description.hpp"
#include "impl/io/atomic_file.hpp"
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
  if (interface == Interface::thesis && kind != Kind::environment)
    throw InputError("--interface thesis",
                     std::string("the thesis interface's ") + (kind == Kind::controller ? "Controller" : "Body") +
                         " runs the thesis's " + (kind == Kind::controller ? "controller" : "20-sim body") +
                         ", which swarmcheck's spec does not have yet: only its Environment can be exported");
  FmuSetup setup;
  setup.kind = kind;
  setup.interface = interface;
  setup.scenario = s;
  setup.scenario.mode = ex::Mode::cosim;
  if (kind == Kind::environment) {
    constexpr int32_t kThesisObstacleSlots = 10;   // ox_1..ox_10 in the thesis's Environment
    setup.robots = static_cast<int32_t>(s.robots.size());
    setup.obstacles = static_cast<int32_t>(s.obstacles.size());
    if (interface == Interface::thesis) setup.obstacles = std::max(setup.obstacles, kThesisObstacleSlots);
  }
  return setup;
}

std::string fmu_archive(const FmuSetup& setup) {
  const std::string id = model_identifier(setup.kind);
  return zip_bytes({{"modelDescription.xml", model_description_xml(setup, ex::kToolVersion)},
                    {"binaries/linux64/" + id + ".so", library_bytes()},
                    {"resources/swarmcheck-fmu.json", setup_to_json(setup)}});
}

void write_fmu(const FmuSetup& setup, const std::string& path) { io::write_file_atomically(path, fmu_archive(setup)); }

void write_intocps(const ex::Scenario& s, Handshake handshake, const std::string& dir, std::optional<double> end_time_s) {
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

  using json_io::Json;
  Json mm;
  // Gauss-Seidel steps instances in this order: the controllers and bodies, then the Environment.
  mm["fmus"] = Json::object({{"{Controller}", "Controller.fmu"}, {"{Body}", "Body.fmu"}, {"{Environment}", "Environment.fmu"}});
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
    parameters[body + "x0"] = s.robots[r][0];
    parameters[body + "y0"] = s.robots[r][1];
    parameters[ctrl + "handshake"] = hs;
  }
  connections[env + "onDestinationOutput"] = on_destination;
  connections[env + "epoch"] = epoch;
  mm["connections"] = connections;
  mm["parameters"] = parameters;

  // The end: the library's completion step for this scenario (the same system), else max_steps,
  // as the engine's clock reads it after that many steps: the repeated sum of step_size (the
  // engine steps while t + h <= endTime, t by repeated addition, so this end gives exactly that
  // many steps; k * h may fall below the sum and lose the last step).
  if (!end_time_s) {
    ex::Scenario as_cosim = s;
    as_cosim.mode = ex::Mode::cosim;
    Exploration run(as_cosim, ExplorationOptions{});
    while (!run.done()) run.step();
    const int64_t steps = run.completion_step().value_or(s.max_steps);
    double t = 0.0;
    for (int64_t k = 0; k < steps; ++k) t = t + s.params.step_size;
    end_time_s = t;
  }
  Json coe;
  coe["startTime"] = 0.0;
  coe["endTime"] = *end_time_s;
  coe["algorithm"] = Json::object({{"type", "fixed-step"}, {"size", s.params.step_size}});
  io::write_file_atomically(in("coe.json"), coe.dump(2) + "\n");
  io::write_file_atomically(in("multimodel.json"), mm.dump(2) + "\n");
}

}  // namespace swarmcheck::fmi
