#pragma once
// Thesis A's 20-sim Body_Block binary's outputs on seven 60 s input profiles (measured data, copied
// from ../shared/fixtures/intocps-body/ into tests/exploration/fixtures/), read for the tests that
// drive the spec's step, the model, the library and the exported FMU with them.
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "spec/exploration/body_intocps.hpp"

namespace swarmcheck::testing {

using exploration::find_intocps_body_parameter;
using exploration::intocps_parameter_ref;
using exploration::IntocpsBodyOutputs;
using exploration::IntocpsBodyParams;

struct Fixture {
  std::string name;
  IntocpsBodyParams params;          // the FMU's defaults, then the fixture's parameters
  std::vector<std::vector<double>> rows;   // k, time, u_L, u_R, then the 9 outputs
};

inline constexpr int kOutputs = 9;   // robot_x, robot_y, robot_theta, robot_z, wheels, encoders, energy

inline Fixture read_fixture(const std::filesystem::path& path) {
  Fixture f;
  f.name = path.filename().string();
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# parameters:", 0) == 0) {
      const std::string text = line.substr(line.find('{'));
      const auto j = nlohmann::json::parse(text.substr(0, text.rfind('}') + 1));
      for (const auto& [name, value] : j.items())
        intocps_parameter_ref(f.params, *find_intocps_body_parameter(name)) = value.get<double>();
    }
    if (line.empty() || line[0] == '#' || line[0] == 'k') continue;
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    f.rows.push_back(row);
  }
  return f;
}

inline std::vector<Fixture> fixtures() {
  std::vector<Fixture> out;
  for (const auto& e : std::filesystem::directory_iterator(SWARMCHECK_SOURCE_DIR "/tests/exploration/fixtures/intocps-body"))
    if (e.path().extension() == ".csv") out.push_back(read_fixture(e.path()));
  std::sort(out.begin(), out.end(), [](const Fixture& a, const Fixture& b) { return a.name < b.name; });
  return out;
}

inline std::array<double, kOutputs> outputs_of(const IntocpsBodyOutputs& o) {
  return {o.robot_x, o.robot_y, o.robot_theta, 0.0, o.wheel_left_rotation, o.wheel_right_rotation,
          o.encoder_left_output, o.encoder_right_output, o.total_energy_used};
}

// The first output of `got` whose bits differ from row k of the fixture, as text; "" if none.
inline std::string compare(const Fixture& f, std::size_t k, const std::array<double, kOutputs>& got) {
  static constexpr const char* kNames[kOutputs] = {"robot_x", "robot_y", "robot_theta", "robot_z", "wheel_left_rotation",
                                         "wheel_right_rotation", "encoder_left_output", "encoder_right_output",
                                         "total_energy_used"};
  for (int c = 0; c < kOutputs; ++c)
    if (std::bit_cast<uint64_t>(got[c]) != std::bit_cast<uint64_t>(f.rows[k][4 + c])) {
      std::ostringstream s;
      s.precision(17);
      s << f.name << " row " << k << " " << kNames[c] << ": got " << got[c] << ", the binary " << f.rows[k][4 + c];
      return s.str();
    }
  return "";
}

}  // namespace swarmcheck::testing
