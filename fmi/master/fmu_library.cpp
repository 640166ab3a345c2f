#include "fmi/master/fmu_library.hpp"

#include <dlfcn.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zip.h>

#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>

#include "spec/util/budget.hpp"
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

// Percent-encodes what a file: URI cannot hold literally.
std::string file_uri(const std::string& path) {
  std::string out = "file://";
  for (const unsigned char c : path) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') out += static_cast<char>(c);
    else {
      char b[4];
      std::snprintf(b, sizeof b, "%%%02X", c);
      out += b;
    }
  }
  return out + "/";
}

// Unpacks every entry of the archive under dir; refuses entries that would land outside it, and
// archives that unpack to more than max_bytes: by the sizes the archive declares, before anything
// is written, and by the bytes actually read (a header may lie). (A 5 MB zip of zeros unpacked to
// 5 GiB in /tmp before.)
void unpack(const std::string& fmu, const std::string& dir, std::uint64_t max_bytes) {
  std::uint64_t unpacked = 0;
  int error = 0;
  zip_t* archive = zip_open(fmu.c_str(), ZIP_RDONLY, &error);
  if (!archive) {
    zip_error_t e;
    zip_error_init_with_code(&e, error);
    const std::string why = zip_error_strerror(&e);
    zip_error_fini(&e);
    throw InputError(fmu, "expected an FMU (a zip archive): " + why);
  }
  const auto close = std::unique_ptr<zip_t, int (*)(zip_t*)>(archive, zip_close);
  const zip_int64_t n = zip_get_num_entries(archive, 0);
  const std::string too_big = "unpacks to more than " + format_bytes(static_cast<double>(max_bytes)) + ": refused as a zip bomb";
  std::uint64_t declared = 0;
  for (zip_int64_t k = 0; k < n; ++k) {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(archive, static_cast<zip_uint64_t>(k), 0, &st) == 0 && (st.valid & ZIP_STAT_SIZE)) declared += st.size;
    if (declared > max_bytes) throw InputError(fmu, too_big + " (by the sizes it declares)");
  }
  for (zip_int64_t k = 0; k < n; ++k) {
    const char* raw = zip_get_name(archive, static_cast<zip_uint64_t>(k), 0);
    if (!raw) throw InputError(fmu, "an archive entry has no name");
    const std::string name = raw;
    const std::filesystem::path rel = std::filesystem::path(name).lexically_normal();
    if (rel.is_absolute() || name.empty() || *rel.begin() == "..")
      throw InputError(fmu, "archive entry '" + name + "' would be written outside the FMU's folder");
    const std::filesystem::path target = std::filesystem::path(dir) / rel;
    // An entry under a path an earlier entry made a file ('binaries', then 'binaries/linux64/x'),
    // or a file where an earlier entry made a folder: an archive no FMU tool writes.
    std::error_code ec;
    std::filesystem::create_directories(name.back() == '/' ? target : target.parent_path(), ec);
    if (ec || (name.back() != '/' && std::filesystem::is_directory(target)))
      throw InputError(fmu, "archive entry '" + name + "' clashes with an earlier entry (a file and a folder of one name)");
    if (name.back() == '/') continue;
    zip_file_t* in = zip_fopen_index(archive, static_cast<zip_uint64_t>(k), 0);
    if (!in) throw InputError(fmu, "cannot read archive entry '" + name + "': " + zip_strerror(archive));
    const auto fclose = std::unique_ptr<zip_file_t, int (*)(zip_file_t*)>(in, zip_fclose);
    std::ofstream out(target, std::ios::binary);
    char buffer[1 << 16];
    zip_int64_t got = 0;
    while ((got = zip_fread(in, buffer, sizeof buffer)) > 0) {
      unpacked += static_cast<std::uint64_t>(got);
      if (unpacked > max_bytes) throw InputError(fmu, too_big + " (at archive entry '" + name + "')");
      out.write(buffer, got);
    }
    if (got < 0 || !out) throw InputError(fmu, "cannot unpack archive entry '" + name + "'");
  }
}

template <class F>
F* symbol(void* handle, const char* name, const std::string& fmu, bool required) {
  void* p = dlsym(handle, name);
  if (!p && required) throw InputError(fmu, std::string("the FMU's library does not export ") + name);
  return reinterpret_cast<F*>(p);
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
    }
    if (!named(n, "ModelVariables")) continue;
    for (xmlNode* v = n->children; v; v = v->next) {
      if (!named(v, "ScalarVariable")) continue;
      ModelVariable mv;
      mv.name = attribute(v, "name");
      const std::string vr = attribute(v, "valueReference");
      char* end = nullptr;
      const unsigned long parsed = std::strtoul(vr.c_str(), &end, 10);
      if (mv.name.empty() || vr.empty() || *end != '\0' || parsed > 0xffffffffUL)
        throw InputError(file + ":" + std::to_string(v->line), "a ScalarVariable needs a name and a valueReference");
      mv.value_reference = static_cast<uint32_t>(parsed);
      mv.causality = has_attribute(v, "causality") ? attribute(v, "causality") : "local";
      mv.variability = has_attribute(v, "variability") ? attribute(v, "variability") : "continuous";
      bool typed = false;
      for (xmlNode* t = v->children; t; t = t->next) {
        if (t->type != XML_ELEMENT_NODE) continue;
        if (named(t, "Real")) mv.type = VarType::real, typed = true;
        else if (named(t, "Integer") || named(t, "Enumeration")) mv.type = VarType::integer, typed = true;
        else if (named(t, "Boolean")) mv.type = VarType::boolean, typed = true;
        else if (named(t, "String")) mv.type = VarType::string, typed = true;
      }
      if (!typed) throw InputError(file + ":" + std::to_string(v->line), "ScalarVariable " + mv.name + " has no type element");
      if (!md.by_name.emplace(mv.name, md.variables.size()).second)
        throw InputError(file + ":" + std::to_string(v->line), "two ScalarVariables are named " + mv.name);
      md.variables.push_back(mv);
    }
  }
  if (md.model_identifier.empty())
    throw InputError(file, "expected a CoSimulation element with a modelIdentifier (a co-simulation FMU)");
  return md;
}

FmuLibrary::FmuLibrary(const std::string& fmu_path, std::uint64_t max_unpacked_bytes) : path_(fmu_path) {
  if (!std::filesystem::exists(fmu_path)) throw InputError(fmu_path, "no such FMU file");
  if (!std::filesystem::is_regular_file(fmu_path)) throw InputError(fmu_path, "expected an FMU file, got a folder or a device");
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/swarmcheck-fmu-XXXXXX";
  if (!mkdtemp(pattern.data())) throw InputError(pattern, "cannot create a temporary folder to unpack the FMU");
  dir_ = pattern;
  try {
    unpack(fmu_path, dir_, max_unpacked_bytes);
    if (!std::filesystem::is_regular_file(dir_ + "/modelDescription.xml"))
      throw InputError(fmu_path, "the archive has no modelDescription.xml file at its top");
    std::ifstream in(dir_ + "/modelDescription.xml", std::ios::binary);
    if (!in) throw InputError(fmu_path, "cannot read its modelDescription.xml");
    const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    description_ = read_model_description(xml, fmu_path + "!modelDescription.xml");
    const std::string so = dir_ + "/binaries/linux64/" + description_.model_identifier + ".so";
    if (!std::filesystem::is_regular_file(so))
      throw InputError(fmu_path, "no binaries/linux64/" + description_.model_identifier + ".so (this master runs linux64 FMUs)");
    handle_ = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) throw InputError(fmu_path, std::string("cannot load its library: ") + dlerror());
    api_.instantiate = symbol<fmi2InstantiateTYPE>(handle_, "fmi2Instantiate", fmu_path, true);
    api_.free_instance = symbol<fmi2FreeInstanceTYPE>(handle_, "fmi2FreeInstance", fmu_path, true);
    api_.setup_experiment = symbol<fmi2SetupExperimentTYPE>(handle_, "fmi2SetupExperiment", fmu_path, true);
    api_.enter_initialization_mode = symbol<fmi2EnterInitializationModeTYPE>(handle_, "fmi2EnterInitializationMode", fmu_path, true);
    api_.exit_initialization_mode = symbol<fmi2ExitInitializationModeTYPE>(handle_, "fmi2ExitInitializationMode", fmu_path, true);
    api_.terminate = symbol<fmi2TerminateTYPE>(handle_, "fmi2Terminate", fmu_path, true);
    api_.get_real = symbol<fmi2GetRealTYPE>(handle_, "fmi2GetReal", fmu_path, true);
    api_.get_integer = symbol<fmi2GetIntegerTYPE>(handle_, "fmi2GetInteger", fmu_path, true);
    api_.get_boolean = symbol<fmi2GetBooleanTYPE>(handle_, "fmi2GetBoolean", fmu_path, true);
    api_.get_string = symbol<fmi2GetStringTYPE>(handle_, "fmi2GetString", fmu_path, true);
    api_.set_real = symbol<fmi2SetRealTYPE>(handle_, "fmi2SetReal", fmu_path, true);
    api_.set_integer = symbol<fmi2SetIntegerTYPE>(handle_, "fmi2SetInteger", fmu_path, true);
    api_.set_boolean = symbol<fmi2SetBooleanTYPE>(handle_, "fmi2SetBoolean", fmu_path, true);
    api_.set_string = symbol<fmi2SetStringTYPE>(handle_, "fmi2SetString", fmu_path, true);
    api_.do_step = symbol<fmi2DoStepTYPE>(handle_, "fmi2DoStep", fmu_path, true);
    api_.get_state = symbol<fmi2GetFMUstateTYPE>(handle_, "fmi2GetFMUstate", fmu_path, false);
    api_.set_state = symbol<fmi2SetFMUstateTYPE>(handle_, "fmi2SetFMUstate", fmu_path, false);
    api_.free_state = symbol<fmi2FreeFMUstateTYPE>(handle_, "fmi2FreeFMUstate", fmu_path, false);
    api_.serialized_state_size = symbol<fmi2SerializedFMUstateSizeTYPE>(handle_, "fmi2SerializedFMUstateSize", fmu_path, false);
    api_.serialize_state = symbol<fmi2SerializeFMUstateTYPE>(handle_, "fmi2SerializeFMUstate", fmu_path, false);
    api_.deserialize_state = symbol<fmi2DeSerializeFMUstateTYPE>(handle_, "fmi2DeSerializeFMUstate", fmu_path, false);
    api_.reset = symbol<fmi2ResetTYPE>(handle_, "fmi2Reset", fmu_path, true);
    resource_uri_ = file_uri(dir_ + "/resources");
  } catch (...) {
    if (handle_) dlclose(handle_);
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    throw;
  }
}

FmuLibrary::~FmuLibrary() {
  if (handle_) dlclose(handle_);
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
}

}  // namespace swarmcheck::fmi::master
