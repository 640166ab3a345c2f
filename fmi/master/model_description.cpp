#include "fmi/master/model_description.hpp"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi::master {
namespace {

std::string attribute(xmlNode* node, const char* name) {
  xmlChar* v = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (!v) return {};
  std::string out(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return out;
}
bool has_attribute(xmlNode* node, const char* name) { return xmlHasProp(node, reinterpret_cast<const xmlChar*>(name)) != nullptr; }
bool named(xmlNode* node, const char* name) {
  return node->type == XML_ELEMENT_NODE && xmlStrcmp(node->name, reinterpret_cast<const xmlChar*>(name)) == 0;
}

// The start attribute of a type element (<Real start="0.5"/>), checked against its type.
void read_start(xmlNode* t, ModelVariable& mv, const std::string& file) {
  if (!has_attribute(t, "start")) return;
  const std::string text = attribute(t, "start");
  const std::string where = file + ":" + std::to_string(t->line);
  const auto bad = [&](const char* expected) {
    return InputError(where, "ScalarVariable " + mv.name + ": start=\"" + text + "\" is not " + expected);
  };
  mv.has_start = true;
  switch (mv.type) {
    case VarType::real: {
      char* end = nullptr;
      errno = 0;
      mv.start_number = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || errno == ERANGE) throw bad("a Real (xs:double)");
      break;
    }
    case VarType::integer: {
      char* end = nullptr;
      errno = 0;
      const long v = std::strtol(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || errno == ERANGE || v < INT32_MIN || v > INT32_MAX) throw bad("an Integer (32 bits)");
      mv.start_number = static_cast<double>(v);
      break;
    }
    case VarType::boolean:
      if (text == "true" || text == "1") mv.start_number = 1;
      else if (text == "false" || text == "0") mv.start_number = 0;
      else throw bad("a Boolean (true, false, 1 or 0)");
      break;
    case VarType::string:
      mv.start_text = text;
      break;
  }
}

}  // namespace

const char* to_string(VarType t) {
  switch (t) {
    case VarType::real: return "Real";
    case VarType::integer: return "Integer";
    case VarType::boolean: return "Boolean";
    case VarType::string: return "String";
  }
  return "?";
}

const ModelVariable* ModelDescription::find(const std::string& name) const {
  const auto it = by_name.find(name);
  return it == by_name.end() ? nullptr : &variables[it->second];
}

ModelDescription read_model_description(const std::string& xml, const std::string& file) {
  const auto doc = std::unique_ptr<xmlDoc, void (*)(xmlDoc*)>(
      xmlReadMemory(xml.data(), static_cast<int>(xml.size()), "modelDescription.xml", nullptr,
                    XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING),
      xmlFreeDoc);
  if (!doc) {
    const xmlError* e = xmlGetLastError();
    std::string why = e && e->message ? e->message : "";
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();   // libxml2 ends it with a newline
    throw InputError(file + (e ? ":" + std::to_string(e->line) : ""),
                     "modelDescription.xml is not well-formed XML" + (why.empty() ? "" : ": " + why));
  }
  xmlNode* root = xmlDocGetRootElement(doc.get());
  if (!root || !named(root, "fmiModelDescription")) throw InputError(file, "expected a root element fmiModelDescription");
  ModelDescription md;
  md.fmi_version = attribute(root, "fmiVersion");
  md.model_name = attribute(root, "modelName");
  md.guid = attribute(root, "guid");
  if (md.fmi_version.rfind("2.", 0) != 0)
    throw InputError(file, "expected fmiVersion 2.0 (FMI 2), got '" + md.fmi_version + "'");
  for (xmlNode* n = root->children; n; n = n->next) {
    if (named(n, "CoSimulation")) {
      md.model_identifier = attribute(n, "modelIdentifier");
      md.can_get_and_set_state = attribute(n, "canGetAndSetFMUstate") == "true";
      md.can_be_instantiated_only_once_per_process = attribute(n, "canBeInstantiatedOnlyOncePerProcess") == "true";
    }
    if (!named(n, "ModelVariables")) continue;
    for (xmlNode* v = n->children; v; v = v->next) {
      if (!named(v, "ScalarVariable")) continue;
      ModelVariable mv;
      mv.name = attribute(v, "name");
      mv.line = static_cast<int>(v->line);
      const std::string vr = attribute(v, "valueReference");
      char* end = nullptr;
      const unsigned long parsed = std::strtoul(vr.c_str(), &end, 10);
      if (mv.name.empty() || vr.empty() || *end != '\0' || parsed > 0xffffffffUL)
        throw InputError(file + ":" + std::to_string(v->line), "a ScalarVariable needs a name and a valueReference");
      mv.value_reference = static_cast<uint32_t>(parsed);
      mv.causality = has_attribute(v, "causality") ? attribute(v, "causality") : "local";
      mv.variability = has_attribute(v, "variability") ? attribute(v, "variability") : "continuous";
      xmlNode* type = nullptr;
      for (xmlNode* t = v->children; t; t = t->next) {
        if (t->type != XML_ELEMENT_NODE) continue;
        if (named(t, "Real")) mv.type = VarType::real, type = t;
        else if (named(t, "Integer") || named(t, "Enumeration")) mv.type = VarType::integer, type = t;
        else if (named(t, "Boolean")) mv.type = VarType::boolean, type = t;
        else if (named(t, "String")) mv.type = VarType::string, type = t;
      }
      if (!type) throw InputError(file + ":" + std::to_string(v->line), "ScalarVariable " + mv.name + " has no type element");
      read_start(type, mv, file);
      if (!md.by_name.emplace(mv.name, md.variables.size()).second)
        throw InputError(file + ":" + std::to_string(v->line), "two ScalarVariables are named " + mv.name);
      md.variables.push_back(mv);
    }
  }
  if (md.model_identifier.empty())
    throw InputError(file, "expected a CoSimulation element with a modelIdentifier (a co-simulation FMU)");
  return md;
}

}  // namespace swarmcheck::fmi::master
