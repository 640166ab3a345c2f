// The `.fsm` writer (precise form, see fsm_io.hpp) and the atomic file write.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>

#include "impl/supervisor/fsm_io.hpp"
#include "spec/util/demand.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::impl::supervisor {

namespace {

std::string attrs(const spec::supervisor::EventAttr& a) {
  return std::string(a.controllable ? "c" : "uc") + "\t" + (a.observable ? "o" : "uo");
}

}  // namespace

std::string write_fsm(const Automaton& a) {
  // Our own operations only produce well-formed automata; writing another is a bug.
  SWARM_DEMAND(spec::supervisor::well_formedness_error(a).empty());
  std::string out = std::to_string(a.states.size()) + "\n\n";
  for (const auto& q : a.states) {
    const auto row = a.delta.find(q);
    const std::size_t n = row == a.delta.end() ? 0 : row->second.size();
    out += q + "\t" + (a.marked.count(q) ? "1" : "0") + "\t" + std::to_string(n) + "\n";
    if (n > 0)
      for (const auto& [e, target] : row->second)
        out += e + "\t" + target + "\t" + attrs(a.events.at(e)) + "\n";
    out += "\n";
  }
  std::set<std::string> used;
  for (const auto& [q, row] : a.delta)
    for (const auto& [e, target] : row) used.insert(e);
  bool header = false;
  for (const auto& [e, attr] : a.events) {
    if (used.count(e)) continue;
    if (!header) out += "EVENTS\n";
    header = true;
    out += e + "\t" + attrs(attr) + "\n";
  }
  return out;
}

void write_file_atomically(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  // A name no concurrent writer picks: the process id is not portable, a random suffix is.
  std::random_device rd;
  std::string temp_name = ".";  // built with += : GCC 12 warns falsely (-Wrestrict) on "." + s
  temp_name += target.filename().string();
  temp_name += ".tmp";
  temp_name += std::to_string(rd());
  const fs::path temp = target.parent_path() / temp_name;
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw InputError(path, "cannot create a temporary file next to it");
    out << content;
    out.flush();
    if (!out) {
      std::error_code ignored;
      fs::remove(temp, ignored);
      throw InputError(path, "cannot write the file");
    }
  }
  std::error_code ec;
  fs::rename(temp, target, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw InputError(path, "cannot replace the file: " + ec.message());
  }
}

}  // namespace swarmcheck::impl::supervisor
