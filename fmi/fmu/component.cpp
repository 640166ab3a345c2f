#include "fmi/fmu/component.hpp"

#include <bit>
#include <cstring>

#include "fmi/fmu/kinds.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"
#include "spec/util/json_text.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi {
namespace {

constexpr char kStateMagic[8] = {'S', 'W', 'F', 'M', 'U', 'S', 'T', '1'};

void put_u64(std::vector<uint8_t>& out, uint64_t v) {
  for (int k = 0; k < 8; ++k) out.push_back(static_cast<uint8_t>(v >> (8 * k)));
}
uint64_t take_u64(std::span<const uint8_t>& in) {
  if (in.size() < 8) throw FmuError("FMU state: the bytes end early (not a state of this FMU)");
  uint64_t v = 0;
  for (int k = 0; k < 8; ++k) v |= uint64_t{in[static_cast<std::size_t>(k)]} << (8 * k);
  in = in.subspan(8);
  return v;
}

}  // namespace

const char* to_string(Kind k) {
  switch (k) {
    case Kind::environment: return "environment";
    case Kind::controller: return "controller";
    case Kind::body: return "body";
  }
  return "environment";
}
std::string model_identifier(Kind k) { return std::string("swarmcheck_") + to_string(k); }
std::string model_name(Kind k) {
  switch (k) {
    case Kind::environment: return "swarmcheck Environment";
    case Kind::controller: return "swarmcheck Controller";
    case Kind::body: return "swarmcheck Body";
  }
  return "";
}

const char* to_string(Interface i) { return i == Interface::thesis ? "thesis" : "swarmcheck"; }

std::string model_name(const FmuSetup& s) {
  if (s.interface == Interface::thesis) return model_name(s.kind) + " (thesis interface)";
  if (s.kind == Kind::body && s.scenario.body.kind == exploration::BodyKind::intocps) return model_name(s.kind) + " (intocps)";
  if (s.kind == Kind::controller && s.scenario.controller == exploration::ControllerKind::thesis)
    return model_name(s.kind) + " (thesis)";
  return model_name(s.kind);
}

void put_state_u64(std::vector<uint8_t>& out, uint64_t v) { put_u64(out, v); }
uint64_t take_state_u64(std::span<const uint8_t>& in) { return take_u64(in); }

std::vector<uint8_t> Component::save() const {
  std::vector<uint8_t> out(std::begin(kStateMagic), std::end(kStateMagic));
  put_u64(out, table_.variables().size());
  for (const Variable& v : table_.variables())
    put_u64(out, v.real ? std::bit_cast<uint64_t>(*v.real) : static_cast<uint64_t>(static_cast<int64_t>(*v.integer)));
  save_extra(out);
  return out;
}

void Component::restore(std::span<const uint8_t> bytes) {
  if (bytes.size() < sizeof kStateMagic || std::memcmp(bytes.data(), kStateMagic, sizeof kStateMagic) != 0)
    throw FmuError("FMU state: not a swarmcheck FMU state (wrong magic bytes)");
  std::span<const uint8_t> in = bytes.subspan(sizeof kStateMagic);
  if (take_u64(in) != table_.variables().size())
    throw FmuError("FMU state: saved by an FMU with another variable list");
  // Read everything before changing anything, so a malformed state leaves the instance as it was.
  std::vector<uint64_t> values;
  for (std::size_t k = 0; k < table_.variables().size(); ++k) values.push_back(take_u64(in));
  const auto before = save();
  std::size_t k = 0;
  for (const Variable& v : table_.variables()) {
    if (v.real) *v.real = std::bit_cast<double>(values[k]);
    else *v.integer = static_cast<int32_t>(static_cast<int64_t>(values[k]));
    ++k;
  }
  try {
    restore_extra(in);
    if (!in.empty()) throw FmuError("FMU state: " + std::to_string(in.size()) + " bytes more than a state has");
  } catch (...) {
    std::span<const uint8_t> back(before);
    back = back.subspan(sizeof kStateMagic + 8);
    for (const Variable& v : table_.variables()) {
      const uint64_t b = take_u64(back);
      if (v.real) *v.real = std::bit_cast<double>(b);
      else *v.integer = static_cast<int32_t>(static_cast<int64_t>(b));
    }
    restore_extra(back);
    throw;
  }
}

std::string setup_to_json(const FmuSetup& s) {
  json_io::Json j;
  j["format"] = "swarmcheck-fmu-1";
  j["kind"] = to_string(s.kind);
  if (s.interface != Interface::swarmcheck) j["interface"] = to_string(s.interface);
  j["robots"] = s.robots;
  j["obstacles"] = s.obstacles;
  j["scenario"] = json_io::to_json(s.scenario);
  return j.dump(2) + "\n";
}

FmuSetup setup_from_json(const std::string& text) {
  // The JSON reader of every input: depth limit, each key once, unknown keys refused.
  json_io::Json j;
  try {
    j = json_io::parse_json_text(text, "resources/swarmcheck-fmu.json");
  } catch (const InputError& e) {
    throw FmuError(e.what());
  }
  try {
    json_io::refuse_unknown_keys(j, "", {"format", "kind", "interface", "robots", "obstacles", "scenario"});
  } catch (const InputError& e) {
    throw FmuError(std::string("resources/swarmcheck-fmu.json: ") + e.what());
  }
  if (!j.is_object() || json_io::string_member(j, "format") != "swarmcheck-fmu-1")
    throw FmuError("resources/swarmcheck-fmu.json: not a swarmcheck FMU setup (format swarmcheck-fmu-1 expected)");
  FmuSetup s;
  const std::string kind = json_io::string_member(j, "kind");
  if (kind == "environment") s.kind = Kind::environment;
  else if (kind == "controller") s.kind = Kind::controller;
  else if (kind == "body") s.kind = Kind::body;
  else throw FmuError("resources/swarmcheck-fmu.json: kind: expected environment, controller or body");
  const std::string interface = j.value("interface", "swarmcheck");
  if (interface == "thesis") s.interface = Interface::thesis;
  else if (interface != "swarmcheck") throw FmuError("resources/swarmcheck-fmu.json: interface: expected swarmcheck or thesis");
  if (!j.contains("robots") || !j["robots"].is_number_integer() || !j.contains("obstacles") ||
      !j["obstacles"].is_number_integer() || !j.contains("scenario"))
    throw FmuError("resources/swarmcheck-fmu.json: robots, obstacles (integers) and scenario expected");
  s.robots = j["robots"].get<int32_t>();
  s.obstacles = j["obstacles"].get<int32_t>();
  try {
    s.scenario = exploration::scenario_from_json(j["scenario"]);
  } catch (const InputError& e) {
    throw FmuError(std::string("resources/swarmcheck-fmu.json: scenario.") + e.what());
  }
  // The thesis interface may have more obstacle slots than the scenario has obstacles.
  if (s.kind == Kind::environment &&
      (s.robots != static_cast<int32_t>(s.scenario.robots.size()) ||
       (s.interface == Interface::swarmcheck ? s.obstacles != static_cast<int32_t>(s.scenario.obstacles.size())
                                             : s.obstacles < static_cast<int32_t>(s.scenario.obstacles.size()))))
    throw FmuError("resources/swarmcheck-fmu.json: robots and obstacles must count the scenario's");
  return s;
}

std::unique_ptr<Component> make_component(const FmuSetup& setup) {
  std::unique_ptr<Component> c;
  switch (setup.kind) {
    case Kind::environment:
      c = setup.interface == Interface::thesis ? make_thesis_environment_component(setup) : make_environment_component(setup);
      break;
    case Kind::controller:
      c = setup.interface == Interface::thesis ? make_thesis_controller_component(setup) : make_controller_component(setup);
      break;
    case Kind::body:
      c = setup.interface == Interface::thesis || setup.scenario.body.kind == exploration::BodyKind::intocps
              ? make_intocps_body_component(setup)
              : make_body_component(setup);
      break;
  }
  c->defaults();
  return c;
}

std::string fmu_guid(const FmuSetup& setup) {
  // FNV-1a over the setup and the variable list with its start values, as a UUID-shaped string.
  const std::unique_ptr<Component> c = make_component(setup);
  std::string text = setup_to_json(setup);
  for (const Variable& v : c->table().variables()) {
    text += v.name + ";" + to_string(v.causality) + ";" + to_string(v.variability) + ";";
    text += v.real ? std::to_string(std::bit_cast<uint64_t>(*v.real)) : std::to_string(*v.integer);
  }
  uint64_t a = 0xcbf29ce484222325ULL, b = 0x84222325cbf29ce4ULL;
  for (const char ch : text) {
    a = (a ^ static_cast<uint8_t>(ch)) * 0x100000001b3ULL;
    b = (b ^ static_cast<uint8_t>(ch)) * 0x100000001b3ULL + 7;
  }
  char out[40];
  std::snprintf(out, sizeof out, "{%08x-%04x-%04x-%04x-%012llx}", static_cast<unsigned>(a >> 32),
                static_cast<unsigned>((a >> 16) & 0xffff), static_cast<unsigned>(a & 0xffff),
                static_cast<unsigned>(b >> 48), static_cast<unsigned long long>(b & 0xffffffffffffULL));
  return out;
}

}  // namespace swarmcheck::fmi
