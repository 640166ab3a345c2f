#include "views/schema.hpp"

#include <limits>

#include "spec/exploration/domains.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/types.hpp"

namespace swarmcheck::views {
namespace {

using json_io::Json;
using namespace swarmcheck::exploration;

template <class T>
Json schema_of();

template <class T>
Json integer_schema() {
  Json j = {{"type", "integer"}};
  // The type's range ("integer N is out of range"), apart from the key's domain (minimum, ...).
  j["x-range"] = Json::array({static_cast<double>(std::numeric_limits<T>::min()),
                              static_cast<double>(std::numeric_limits<T>::max())});
  j["x-integer"] = std::is_unsigned_v<T> ? "unsigned" : "signed";
  return j;
}

// A scenario's body: a name, or {"kind": name, "parameters": {Body_Block name: number}}
// (json_io::JsonCodec<BodyChoice>); the parameters' names and defaults come with it.
Json body_schema() {
  Json kinds = Json::array();
  for (const BodyDescriptor& b : kBodies) kinds.push_back(std::string(b.name));
  Json names = Json::array();
  Json defaults = Json::object();
  const IntocpsBodyParams d = scenario_intocps_params();
  for (const IntocpsBodyParameter& p : intocps_body_parameters()) {
    names.push_back(std::string(p.name));
    defaults[std::string(p.name)] = intocps_parameter_value(d, p);
  }
  return {{"type", "x-body"}, {"enum", kinds}, {"x-parameters", names}, {"x-parameter-defaults", defaults}};
}

template <class T>
Json schema_of() {
  if constexpr (std::is_same_v<T, BodyChoice>) {
    return body_schema();
  } else if constexpr (json_io::is_hana_struct<T>) {
    Json props = Json::object();
    Json order = Json::array();
    boost::hana::for_each(boost::hana::accessors<T>(), [&](auto pair) {
      using Member = std::decay_t<decltype(boost::hana::second(pair)(std::declval<const T&>()))>;
      const char* name = boost::hana::to<const char*>(boost::hana::first(pair));
      props[name] = schema_of<Member>();
      order.push_back(name);
    });
    return {{"type", "object"}, {"properties", props}, {"additionalProperties", false}, {"x-order", order}};
  } else if constexpr (std::is_enum_v<T>) {
    Json names = Json::array();
    for (const auto& [value, name] : json_io::EnumNames<T>::names) {
      (void)value;
      names.push_back(std::string(name));
    }
    return {{"type", "string"}, {"enum", names}};
  } else if constexpr (std::is_same_v<T, bool>) {
    return {{"type", "boolean"}};
  } else if constexpr (std::is_integral_v<T>) {
    return integer_schema<T>();
  } else if constexpr (std::is_floating_point_v<T>) {
    return {{"type", "number"}};
  } else if constexpr (json_io::IsVector<T>::value) {
    return {{"type", "array"}, {"items", schema_of<typename T::value_type>()}};
  } else if constexpr (json_io::IsArray<T>::value) {
    constexpr std::size_t n = std::tuple_size_v<T>;
    return {{"type", "array"}, {"items", schema_of<typename T::value_type>()}, {"minItems", n}, {"maxItems", n}};
  } else {
    static_assert(sizeof(T) == 0, "schema_of: unsupported member type");
  }
}

Json& at_path(Json& schema, std::string_view path) {
  Json* node = &schema;
  std::size_t pos = 0;
  while (pos <= path.size()) {
    const std::size_t dot = path.find('.', pos);
    const std::string key(path.substr(pos, dot == std::string_view::npos ? std::string_view::npos : dot - pos));
    node = &(*node)["properties"][key];
    if (dot == std::string_view::npos) break;
    pos = dot + 1;
  }
  return *node;
}

}  // namespace

json_io::Json scenario_schema() {
  Json s = schema_of<Scenario>();
  s["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  s["title"] = "swarmcheck scenario";
  s["required"] = Json::array({"map_size", "robots"});
  s["x-required-messages"] = {{"map_size", "missing (the map's side in cells)"},
                              {"robots", "missing (a list of [x, y] positions)"}};
  for (const Domain& d : kScenarioDomains) {
    Json& node = at_path(s, d.path);
    if (d.has_min) node[d.min_exclusive ? "exclusiveMinimum" : "minimum"] = d.min;
    if (d.has_max) node["maximum"] = d.max;
    node["x-expected"] = d.expected;
    node["x-stage"] = d.stage == DomainStage::before_cells ? "before_cells"
                      : d.stage == DomainStage::params   ? "params"
                                                         : "after_params";
  }
  Json rules = Json::array();
  for (const auto r : kScenarioRules) rules.push_back(std::string(r));
  s["x-rules"] = rules;
  s["x-limits"] = {{"cosim_step_max_s", kCosimStepMax_s}, {"deposit_max", kDepositMax}, {"robots_max", kRobotsMax}};
  s["x-default"] = json_io::to_json(default_scenario());
  s["x-default"]["obstacles"] = Json::array();
  return s;
}

}  // namespace swarmcheck::views
