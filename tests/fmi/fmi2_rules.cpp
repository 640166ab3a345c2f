#include "tests/fmi/fmi2_rules.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>
#include <set>

namespace swarmcheck::testing {
namespace {

bool is(xmlNode* n, const char* name) {
  return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, reinterpret_cast<const xmlChar*>(name)) == 0;
}
bool has(xmlNode* n, const char* a) { return xmlHasProp(n, reinterpret_cast<const xmlChar*>(a)) != nullptr; }
std::string attr(xmlNode* n, const char* a) {
  xmlChar* v = xmlGetProp(n, reinterpret_cast<const xmlChar*>(a));
  if (!v) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}
bool unsigned_int(const std::string& s) {
  if (s.empty() || s.size() > 10) return false;
  for (const char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return std::strtoull(s.c_str(), nullptr, 10) <= 0xffffffffULL;
}
bool c_identifier(const std::string& s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (const char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// FMI 2.0 section 2.2.7: which variabilities each causality may have.
bool legal_combination(const std::string& causality, const std::string& variability) {
  static const std::map<std::string, std::set<std::string>> allowed = {
      {"constant", {"output", "local"}},
      {"fixed", {"parameter", "calculatedParameter", "local"}},
      {"tunable", {"parameter", "calculatedParameter", "local"}},
      {"discrete", {"input", "output", "local"}},
      {"continuous", {"input", "output", "local", "independent"}},
  };
  const auto it = allowed.find(variability);
  return it != allowed.end() && it->second.count(causality) == 1;
}

// The initial values allowed for a legal combination (empty set: the attribute must be absent),
// and the default when it is absent.
std::pair<std::set<std::string>, std::string> initial_rule(const std::string& causality, const std::string& variability) {
  if (variability == "constant") return {{"exact"}, "exact"};
  if (causality == "parameter") return {{"exact"}, "exact"};
  if (causality == "calculatedParameter") return {{"calculated", "approx"}, "calculated"};
  if (causality == "input" || causality == "independent") return {{}, ""};
  if (variability == "fixed" || variability == "tunable") return {{"calculated", "approx"}, "calculated"};
  return {{"exact", "approx", "calculated"}, "calculated"};   // output, local; discrete, continuous
}

}  // namespace

std::vector<std::string> fmi2_problems(const std::string& xml) {
  std::vector<std::string> p;
  const auto doc = std::unique_ptr<xmlDoc, void (*)(xmlDoc*)>(
      xmlReadMemory(xml.data(), static_cast<int>(xml.size()), "modelDescription.xml", nullptr,
                    XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING),
      xmlFreeDoc);
  if (!doc) return {"not well-formed XML"};
  xmlNode* root = xmlDocGetRootElement(doc.get());
  if (!root || !is(root, "fmiModelDescription")) return {"the root element is not fmiModelDescription"};
  if (attr(root, "fmiVersion") != "2.0") p.push_back("fmiVersion must be \"2.0\"");
  for (const char* a : {"modelName", "guid"})
    if (attr(root, a).empty()) p.push_back(std::string("fmiModelDescription needs ") + a);
  if (has(root, "variableNamingConvention") && attr(root, "variableNamingConvention") != "flat" &&
      attr(root, "variableNamingConvention") != "structured")
    p.push_back("variableNamingConvention must be flat or structured");

  int co_simulation = 0, model_exchange = 0, model_variables = 0, model_structure = 0;
  struct Var {
    std::string name, causality, variability, initial, type;
    bool start = false;
  };
  std::vector<Var> vars;
  xmlNode* structure = nullptr;
  for (xmlNode* n = root->children; n; n = n->next) {
    if (is(n, "CoSimulation")) {
      ++co_simulation;
      if (!c_identifier(attr(n, "modelIdentifier"))) p.push_back("CoSimulation needs a modelIdentifier that is a C identifier");
    }
    if (is(n, "ModelExchange")) ++model_exchange;
    if (is(n, "ModelStructure")) {
      ++model_structure;
      structure = n;
    }
    if (!is(n, "ModelVariables")) continue;
    ++model_variables;
    std::set<std::string> names;
    std::set<std::pair<std::string, std::string>> references;   // (base type, valueReference)
    for (xmlNode* v = n->children; v; v = v->next) {
      if (v->type != XML_ELEMENT_NODE) continue;
      if (!is(v, "ScalarVariable")) {
        p.push_back("ModelVariables holds an element other than ScalarVariable");
        continue;
      }
      Var var;
      var.name = attr(v, "name");
      const std::string where = "ScalarVariable " + (var.name.empty() ? "#" + std::to_string(vars.size() + 1) : var.name);
      if (var.name.empty()) p.push_back(where + ": no name");
      if (!names.insert(var.name).second) p.push_back(where + ": name used twice");
      const std::string vr = attr(v, "valueReference");
      if (!unsigned_int(vr)) p.push_back(where + ": valueReference must be an unsigned 32-bit integer");
      var.causality = has(v, "causality") ? attr(v, "causality") : "local";
      var.variability = has(v, "variability") ? attr(v, "variability") : "continuous";
      static const std::set<std::string> causalities{"parameter", "calculatedParameter", "input", "output", "local", "independent"};
      static const std::set<std::string> variabilities{"constant", "fixed", "tunable", "discrete", "continuous"};
      if (!causalities.count(var.causality)) p.push_back(where + ": unknown causality " + var.causality);
      if (!variabilities.count(var.variability)) p.push_back(where + ": unknown variability " + var.variability);
      if (!legal_combination(var.causality, var.variability))
        p.push_back(where + ": causality " + var.causality + " with variability " + var.variability + " is not allowed");
      const auto [initials, default_initial] = initial_rule(var.causality, var.variability);
      if (has(v, "initial")) {
        var.initial = attr(v, "initial");
        if (!initials.count(var.initial))
          p.push_back(where + ": initial " + var.initial + " is not allowed for " + var.causality + "/" + var.variability);
      } else {
        var.initial = default_initial;
      }
      int types = 0;
      for (xmlNode* t = v->children; t; t = t->next) {
        if (t->type != XML_ELEMENT_NODE) continue;
        ++types;
        var.type = reinterpret_cast<const char*>(t->name);
        var.start = has(t, "start");
        static const std::set<std::string> kinds{"Real", "Integer", "Boolean", "String", "Enumeration"};
        if (!kinds.count(var.type)) p.push_back(where + ": unknown type element " + var.type);
      }
      if (types != 1) p.push_back(where + ": needs exactly one type element, has " + std::to_string(types));
      if (var.type != "Real" && var.variability == "continuous") p.push_back(where + ": only Real variables may be continuous");
      const bool start_required = var.initial == "exact" || var.initial == "approx" || var.causality == "input";
      const bool start_forbidden = var.initial == "calculated" || var.causality == "independent";
      if (start_required && !var.start) p.push_back(where + ": needs a start value");
      if (start_forbidden && var.start) p.push_back(where + ": must not have a start value");
      if (!references.insert({var.type, vr}).second) p.push_back(where + ": valueReference " + vr + " used twice for " + var.type);
      vars.push_back(var);
    }
  }
  if (co_simulation + model_exchange == 0) p.push_back("neither CoSimulation nor ModelExchange");
  if (model_variables != 1) p.push_back("needs exactly one ModelVariables");
  if (model_structure != 1 || !structure) {
    p.push_back("needs exactly one ModelStructure");
    return p;
  }
  // Outputs: exactly the variables with causality output; InitialUnknowns: exactly the outputs with
  // initial approx / calculated and the calculated parameters (co-simulation: no states).
  std::vector<std::size_t> outputs, initial_unknowns;
  for (std::size_t k = 0; k < vars.size(); ++k) {
    if (vars[k].causality == "output") outputs.push_back(k + 1);
    if ((vars[k].causality == "output" && (vars[k].initial == "approx" || vars[k].initial == "calculated")) ||
        vars[k].causality == "calculatedParameter")
      initial_unknowns.push_back(k + 1);
  }
  const auto listed = [&](const char* section, const std::vector<std::size_t>& expected) {
    std::vector<std::size_t> got;
    bool present = false;
    for (xmlNode* s = structure->children; s; s = s->next) {
      if (!is(s, section)) continue;
      present = true;
      for (xmlNode* u = s->children; u; u = u->next) {
        if (u->type != XML_ELEMENT_NODE) continue;
        if (!is(u, "Unknown") || !unsigned_int(attr(u, "index"))) {
          p.push_back(std::string(section) + ": an entry that is not <Unknown index=\"N\">");
          continue;
        }
        got.push_back(std::strtoull(attr(u, "index").c_str(), nullptr, 10));
        if (has(u, "dependencies")) {
          const std::string deps = attr(u, "dependencies");
          std::size_t at = 0;
          while (at < deps.size()) {
            const std::size_t end = deps.find(' ', at);
            const std::string d = deps.substr(at, end == std::string::npos ? std::string::npos : end - at);
            if (!d.empty() && (!unsigned_int(d) || std::strtoull(d.c_str(), nullptr, 10) == 0 ||
                               std::strtoull(d.c_str(), nullptr, 10) > vars.size()))
              p.push_back(std::string(section) + ": dependency " + d + " is not a variable index");
            if (end == std::string::npos) break;
            at = end + 1;
          }
        }
      }
    }
    if (!present && !expected.empty()) p.push_back(std::string("ModelStructure lacks ") + section);
    for (std::size_t k = 1; k < got.size(); ++k)
      if (got[k] <= got[k - 1]) p.push_back(std::string(section) + ": indices not in ascending order");
    if (got != expected)
      p.push_back(std::string(section) + " lists " + std::to_string(got.size()) + " variables; the rules want " +
                  std::to_string(expected.size()) + " (exactly those, by index)");
  };
  listed("Outputs", outputs);
  listed("InitialUnknowns", initial_unknowns);
  return p;
}

}  // namespace swarmcheck::testing
