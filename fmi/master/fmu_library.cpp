#include "fmi/master/fmu_library.hpp"
#include "impl/io/interrupt.hpp"

#include <dlfcn.h>
#include <zip.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "spec/util/budget.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi::master {
namespace {

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

// The libraries shipped in binaries/linux64 beside the model's (any *.so* file but `model`), by
// name.
std::vector<std::string> shipped_libraries(const std::string& folder, const std::string& model) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && name != model && name.find(".so") != std::string::npos) out.push_back(e.path().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

FmuLibrary::Copy FmuLibrary::load(const std::string& so) const {
  Copy c;
  c.handle = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!c.handle) throw InputError(path_, std::string("cannot load its library: ") + dlerror());
  try {
    const std::string& f = path_;
    c.api.instantiate = symbol<fmi2InstantiateTYPE>(c.handle, "fmi2Instantiate", f, true);
    c.api.free_instance = symbol<fmi2FreeInstanceTYPE>(c.handle, "fmi2FreeInstance", f, true);
    c.api.setup_experiment = symbol<fmi2SetupExperimentTYPE>(c.handle, "fmi2SetupExperiment", f, true);
    c.api.enter_initialization_mode = symbol<fmi2EnterInitializationModeTYPE>(c.handle, "fmi2EnterInitializationMode", f, true);
    c.api.exit_initialization_mode = symbol<fmi2ExitInitializationModeTYPE>(c.handle, "fmi2ExitInitializationMode", f, true);
    c.api.terminate = symbol<fmi2TerminateTYPE>(c.handle, "fmi2Terminate", f, true);
    c.api.get_real = symbol<fmi2GetRealTYPE>(c.handle, "fmi2GetReal", f, true);
    c.api.get_integer = symbol<fmi2GetIntegerTYPE>(c.handle, "fmi2GetInteger", f, true);
    c.api.get_boolean = symbol<fmi2GetBooleanTYPE>(c.handle, "fmi2GetBoolean", f, true);
    c.api.get_string = symbol<fmi2GetStringTYPE>(c.handle, "fmi2GetString", f, true);
    c.api.set_real = symbol<fmi2SetRealTYPE>(c.handle, "fmi2SetReal", f, true);
    c.api.set_integer = symbol<fmi2SetIntegerTYPE>(c.handle, "fmi2SetInteger", f, true);
    c.api.set_boolean = symbol<fmi2SetBooleanTYPE>(c.handle, "fmi2SetBoolean", f, true);
    c.api.set_string = symbol<fmi2SetStringTYPE>(c.handle, "fmi2SetString", f, true);
    c.api.do_step = symbol<fmi2DoStepTYPE>(c.handle, "fmi2DoStep", f, true);
    c.api.get_state = symbol<fmi2GetFMUstateTYPE>(c.handle, "fmi2GetFMUstate", f, false);
    c.api.set_state = symbol<fmi2SetFMUstateTYPE>(c.handle, "fmi2SetFMUstate", f, false);
    c.api.free_state = symbol<fmi2FreeFMUstateTYPE>(c.handle, "fmi2FreeFMUstate", f, false);
    c.api.serialized_state_size = symbol<fmi2SerializedFMUstateSizeTYPE>(c.handle, "fmi2SerializedFMUstateSize", f, false);
    c.api.serialize_state = symbol<fmi2SerializeFMUstateTYPE>(c.handle, "fmi2SerializeFMUstate", f, false);
    c.api.deserialize_state = symbol<fmi2DeSerializeFMUstateTYPE>(c.handle, "fmi2DeSerializeFMUstate", f, false);
    c.api.reset = symbol<fmi2ResetTYPE>(c.handle, "fmi2Reset", f, true);
  } catch (...) {
    dlclose(c.handle);
    throw;
  }
  return c;
}

FmuLibrary::FmuLibrary(const std::string& fmu_path, std::uint64_t max_unpacked_bytes) : path_(fmu_path) {
  if (!std::filesystem::exists(fmu_path)) throw InputError(fmu_path, "no such FMU file");
  if (!std::filesystem::is_regular_file(fmu_path)) throw InputError(fmu_path, "expected an FMU file, got a folder or a device");
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/swarmcheck-fmu-XXXXXX";
  if (!mkdtemp(pattern.data())) throw InputError(pattern, "cannot create a temporary folder to unpack the FMU");
  dir_ = pattern;
  temp_slot_ = impl::io::register_temp_folder(dir_.c_str());
  try {
    unpack(fmu_path, dir_, max_unpacked_bytes);
    if (!std::filesystem::is_regular_file(dir_ + "/modelDescription.xml"))
      throw InputError(fmu_path, "the archive has no modelDescription.xml file at its top");
    std::ifstream in(dir_ + "/modelDescription.xml", std::ios::binary);
    if (!in) throw InputError(fmu_path, "cannot read its modelDescription.xml");
    const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    description_ = read_model_description(xml, fmu_path + "!modelDescription.xml");
    const std::string binaries = dir_ + "/binaries/linux64";
    const std::string model = description_.model_identifier + ".so";
    so_ = binaries + "/" + model;
    if (!std::filesystem::is_regular_file(so_))
      throw InputError(fmu_path, "no binaries/linux64/" + model + " (this master runs linux64 FMUs)");
    // The shipped libraries may need each other: loaded in rounds until none more loads (an FMU
    // may also ship files the model does not need and that do not load here; they only matter
    // if the model's library then fails to load, and are named in its message).
    std::vector<std::string> pending = shipped_libraries(binaries, model);
    std::vector<std::string> refused;
    for (bool progress = true; progress && !pending.empty();) {
      progress = false;
      refused.clear();
      std::vector<std::string> still;
      for (const std::string& lib : pending) {
        if (void* h = dlopen(lib.c_str(), RTLD_LAZY | RTLD_LOCAL)) {
          shipped_.push_back(h);
          progress = true;
        } else {
          still.push_back(lib);
          refused.push_back(dlerror());
        }
      }
      pending = std::move(still);
    }
    try {
      copies_.push_back(std::make_unique<Copy>(load(so_)));
    } catch (const InputError& e) {
      std::string also;
      for (const std::string& r : refused) also += "; a library it ships did not load either: " + r;
      throw InputError("", e.what() + also);
    }
    resource_uri_ = file_uri(dir_ + "/resources");
  } catch (...) {
    unload();
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
    impl::io::release_temp_file(temp_slot_);
    throw;
  }
}

std::size_t FmuLibrary::load_copy() {
  const std::string copy = so_.substr(0, so_.size() - 3) + ".copy" + std::to_string(copies_.size()) + ".so";
  std::error_code ec;
  std::filesystem::copy_file(so_, copy, std::filesystem::copy_options::overwrite_existing, ec);
  if (ec) throw InputError(path_, "cannot copy its library for one more instance: " + ec.message());
  copies_.push_back(std::make_unique<Copy>(load(copy)));
  return copies_.size() - 1;
}

void FmuLibrary::unload() {
  if (keep_loaded_) return;
  for (auto c = copies_.rbegin(); c != copies_.rend(); ++c) dlclose((*c)->handle);
  for (auto h = shipped_.rbegin(); h != shipped_.rend(); ++h) dlclose(*h);
  copies_.clear();
  shipped_.clear();
}

FmuLibrary::~FmuLibrary() {
  unload();
  std::error_code ec;
  std::filesystem::remove_all(dir_, ec);
  impl::io::release_temp_file(temp_slot_);
}

}  // namespace swarmcheck::fmi::master
