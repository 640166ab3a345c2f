#pragma once
// A private folder per test process, and FMUs exported into it.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fmi/export/fmu_export.hpp"

namespace swarmcheck::testing {

inline std::filesystem::path fmi_scratch(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() /
                 ("swarmcheck-fmi-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

inline std::string export_fmu(const std::filesystem::path& dir, fmi::Kind kind, const exploration::Scenario& s) {
  const std::string path = (dir / (std::string(fmi::to_string(kind)) + ".fmu")).string();
  fmi::write_fmu(fmi::fmu_setup(kind, s), path);
  return path;
}

}  // namespace swarmcheck::testing
