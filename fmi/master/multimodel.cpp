#include "fmi/master/multimodel.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <initializer_list>
#include <filesystem>
#include <unordered_map>

#include "spec/util/hana_json.hpp"
#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::fmi::master {
namespace {

using json_io::Json;

Json parse_file(const std::string& path, const char* what) {
  return json_io::parse_json_text(io_input::read_input_file(path, what), path);
}

// "{FMU}.instance.variable": the FMU key is braced, the instance has no dot; the variable is the rest.
PortName port_name(const std::string& text, const std::string& file, const std::string& where) {
  const std::size_t close = text.find('}');
  const std::size_t dot1 = close == std::string::npos ? std::string::npos : text.find('.', close);
  const std::size_t dot2 = dot1 == std::string::npos ? std::string::npos : text.find('.', dot1 + 1);
  if (text.empty() || text[0] != '{' || close == std::string::npos || dot1 != close + 1 || dot2 == std::string::npos ||
      dot2 == dot1 + 1 || dot2 + 1 >= text.size())
    throw InputError(file + ": " + where, "expected \"{FMU}.instance.variable\", got \"" + text + "\"");
  // Names become columns of outputs.csv and words of messages: no control characters, no quotes or commas.
  for (const unsigned char c : text)
    if (c < 0x20 || c == 0x7f || c == '"' || c == ',')
      throw InputError(file + ": " + where, "expected a name without control characters, quotes or commas");
  return PortName{text.substr(0, close + 1), text.substr(dot1 + 1, dot2 - dot1 - 1), text.substr(dot2 + 1)};
}

// INTO-CPS files carry many keys this master does not use (logging, live graphs, ...), so unknown
// keys are allowed; but one a letter or a letter's case away from a key it reads is a misspelling
// ("endtime" ran the default 10 s, "paramters" set nothing), and is refused.
bool near_miss(const std::string& key, const std::string& known) {
  if (key == known) return false;
  const auto lower = [](std::string t) {
    for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return t;
  };
  const std::string a = lower(key), b = lower(known);
  if (a == b) return true;
  if (b.size() < 4 || (a.size() > b.size() ? a.size() - b.size() : b.size() - a.size()) > 1) return false;
  // Levenshtein distance 1: one letter inserted, deleted or changed.
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  return a.substr(i + (a.size() >= b.size() ? 1 : 0)) == b.substr(i + (b.size() >= a.size() ? 1 : 0));
}

void refuse_misspellings(const Json& object, std::initializer_list<const char*> known, const std::string& where) {
  for (const auto& [key, value] : object.items())
    for (const char* k : known)
      if (near_miss(key, k))
        throw InputError(where + key, std::string("unknown key: did you mean \"") + k + "\"?");
}

// A configuration's keys are all known (what the INTO-CPS engine writes): anything else is
// refused, a misspelling with the key it resembles.
void refuse_unknown(const Json& object, std::initializer_list<const char*> known, const std::string& where) {
  refuse_misspellings(object, known, where);
  for (const auto& [key, value] : object.items()) {
    bool found = false;
    for (const char* k : known) found = found || key == k;
    if (found) continue;
    std::string list;
    for (const char* k : known) list += std::string(list.empty() ? "" : ", ") + k;
    throw InputError(where + key, "unknown key: expected one of the INTO-CPS engine's (" + list + ")");
  }
}

// Where an FMU file named in a multi-model is: next to the multi-model, else in the INTO-CPS
// project's FMUs/ folder (the parent of the nearest enclosing Multi-models/ folder), else (for
// the message) next to the multi-model.
std::filesystem::path fmu_file(const std::filesystem::path& folder, const std::filesystem::path& file) {
  if (file.is_absolute()) return file;
  const std::filesystem::path beside = folder / file;
  std::error_code ec;
  if (std::filesystem::exists(beside, ec)) return beside;
  const std::filesystem::path absolute = std::filesystem::absolute(folder, ec);
  for (std::filesystem::path p = absolute; !ec && p.has_relative_path(); p = p.parent_path())
    if (p.filename() == "Multi-models") {
      const std::filesystem::path in_project = p.parent_path() / "FMUs" / file;
      if (std::filesystem::exists(in_project, ec)) return in_project;
      break;
    }
  return beside;
}

}  // namespace

MultiModel read_multimodel(const std::string& path) {
  const Json j = parse_file(path, "multi-model");
  MultiModel mm;
  mm.file = path;
  if (!j.is_object()) throw InputError(path, "expected a JSON object (an INTO-CPS multi-model)");
  refuse_misspellings(j, {"fmus", "connections", "parameters"}, path + ": ");
  if (!j.contains("fmus") || !j["fmus"].is_object() || j["fmus"].empty())
    throw InputError(path + ": fmus", "expected an object of \"{FMU}\": \"file.fmu\" (at least one)");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const auto& [key, value] : j["fmus"].items()) {
    if (key.size() < 3 || key.front() != '{' || key.back() != '}' || key.find('.') != std::string::npos)
      throw InputError(path + ": fmus." + key, "expected an FMU key written {Name}");
    if (!value.is_string()) throw InputError(path + ": fmus." + key, "expected the FMU's file name (a string)");
    std::string file = value.get<std::string>();
    if (file.rfind("file://", 0) == 0) file = file.substr(7);
    mm.fmus.emplace_back(key, fmu_file(folder, file).string());
  }
  const auto known_fmu = [&](const PortName& p, const std::string& where) {
    for (const auto& [key, file] : mm.fmus)
      if (key == p.fmu) return;
    throw InputError(path + ": " + where, "FMU " + p.fmu + " is not in \"fmus\"");
  };
  std::vector<std::pair<std::string, std::string>> seen;   // in order of appearance
  std::unordered_map<std::string, bool> seen_label;
  const auto note_instance = [&](const PortName& p) {
    if (seen_label.emplace(p.fmu + "." + p.instance, true).second) seen.emplace_back(p.fmu, p.instance);
  };
  std::unordered_map<std::string, std::string> target_at;   // input -> where it is connected
  if (j.contains("connections")) {
    if (!j["connections"].is_object()) throw InputError(path + ": connections", "expected an object");
    for (const auto& [from, targets] : j["connections"].items()) {
      const std::string where = "connections." + from;
      const PortName src = port_name(from, path, where);
      known_fmu(src, where);
      note_instance(src);
      if (!targets.is_array()) throw InputError(path + ": " + where, "expected a list of \"{FMU}.instance.input\"");
      for (std::size_t k = 0; k < targets.size(); ++k) {
        const std::string w = where + "[" + std::to_string(k) + "]";
        if (!targets[k].is_string()) throw InputError(path + ": " + w, "expected \"{FMU}.instance.input\"");
        const PortName dst = port_name(targets[k].get<std::string>(), path, w);
        known_fmu(dst, w);
        note_instance(dst);
        const auto [at, fresh] = target_at.emplace(dst.text(), w);
        if (!fresh) throw InputError(path + ": " + w, "input " + dst.text() + " is connected twice (also at " + at->second + ")");
        mm.connections.push_back(Connection{src, dst, w});
      }
    }
  }
  if (j.contains("parameters")) {
    if (!j["parameters"].is_object()) throw InputError(path + ": parameters", "expected an object");
    for (const auto& [name, value] : j["parameters"].items()) {
      const std::string where = "parameters." + name;
      const PortName p = port_name(name, path, where);
      known_fmu(p, where);
      note_instance(p);
      Parameter par;
      par.port = p;
      par.where = where;
      if (value.is_boolean()) par.value = value.get<bool>() ? 1 : 0, par.integral = true;
      else if (value.is_number_integer()) par.value = value.get<double>(), par.integral = true;
      else if (value.is_number()) par.value = value.get<double>();
      else if (value.is_string()) par.text = value.get<std::string>(), par.is_text = true;
      else throw InputError(path + ": " + where, "expected a number, a boolean or a string");
      mm.parameters.push_back(par);
    }
  }
  for (const auto& [key, file] : mm.fmus)
    for (const auto& s : seen)
      if (s.first == key) mm.instances.push_back(s);
  if (mm.instances.empty()) throw InputError(path, "no instance: name instances in connections or parameters");
  return mm;
}

CoSimConfig read_config(const std::string& path) {
  CoSimConfig c;
  if (path.empty()) return c;
  const Json j = parse_file(path, "co-simulation configuration");
  if (!j.is_object()) throw InputError(path, "expected a JSON object (an INTO-CPS co-simulation configuration)");
  if (j.contains("fmus"))
    throw InputError(path, "is a multi-model (it has \"fmus\"), not a co-simulation configuration (startTime, endTime, "
                           "algorithm): give the multi-model first and this with --config only if it is one (a run "
                           "folder's config.json holds both: give it as the multi-model, its coe.json with --config)");
  refuse_unknown(j, {"startTime", "endTime", "algorithm", "logVariables", "multimodel_path", "multimodel_crc",
                     "liveGraphColumns", "liveGraphVisibleRowCount", "graphs", "livestreamInterval", "livestream",
                     "visible", "loggingOn", "overrideLogLevel", "enableAllLogCategoriesPerInstance",
                     "postProcessingScript", "parallelSimulation", "stabalizationEnabled", "global_absolute_tolerance",
                     "global_relative_tolerance", "simulationProgramDelay", "reportProgress", "liveLogInterval",
                     "logLevels"},
                 path + ": ");
  if (j.contains("algorithm") && j["algorithm"].is_object()) refuse_unknown(j["algorithm"], {"type", "size"}, path + ": algorithm.");
  if (j.contains("stabalizationEnabled") && j["stabalizationEnabled"] != false)
    throw InputError(path + ": stabalizationEnabled", "expected false: this master takes each step once (no iterated, "
                                                      "stabilised steps)");
  if (j.contains("logVariables")) {
    const Json& log = j["logVariables"];
    if (!log.is_object())
      throw InputError(path + ": logVariables", "expected an object of \"{FMU}.instance\": [\"variable\", ...]");
    for (const auto& [instance, names] : log.items()) {
      const std::string where = "logVariables." + instance;
      if (!names.is_array()) throw InputError(path + ": " + where, "expected a list of variable names");
      for (std::size_t k = 0; k < names.size(); ++k) {
        const std::string w = where + "[" + std::to_string(k) + "]";
        if (!names[k].is_string()) throw InputError(path + ": " + w, "expected a variable name");
        c.log_variables.push_back(LogVariable{port_name(instance + "." + names[k].get<std::string>(), path, w), path + ": " + w});
      }
    }
  }
  const auto number = [&](const Json& v, const std::string& where) {
    if (!v.is_number() || !std::isfinite(v.get<double>())) throw InputError(path + ": " + where, "expected a finite number");
    return v.get<double>();
  };
  if (j.contains("startTime")) c.start_s = number(j["startTime"], "startTime");
  if (j.contains("endTime")) c.end_s = number(j["endTime"], "endTime");
  if (j.contains("algorithm")) {
    const Json& a = j["algorithm"];
    if (!a.is_object() || json_io::string_member(a, "type") != "fixed-step")   // any type: a message, not a type_error
      throw InputError(path + ": algorithm.type", "expected \"fixed-step\" (the one algorithm this master runs)");
    if (!a.contains("size")) throw InputError(path + ": algorithm.size", "expected the step size, s");
    c.step_s = number(a["size"], "algorithm.size");
  }
  if (!(c.step_s > 0)) throw InputError(path + ": algorithm.size", "expected a step size > 0");
  if (!(c.end_s >= c.start_s)) throw InputError(path + ": endTime", "expected endTime >= startTime");
  if ((c.end_s - c.start_s) / c.step_s > 1e9) throw InputError(path + ": endTime", "expected at most 10^9 steps");
  if (c.end_s > c.start_s && c.step_s > c.end_s - c.start_s)
    throw InputError(path + ": algorithm.size", fmt::format("expected a step of at most endTime - startTime ({} s): "
                                                            "a step of {} s runs none", c.end_s - c.start_s, c.step_s));
  return c;
}

}  // namespace swarmcheck::fmi::master
