// The exported FMUs load anywhere and pass third-party checkers with their defaults: the library
// needs glibc's libraries only (`ldd`: no libstdc++, libgcc_s, libfmt, libtbb), glibc 2.35 or
// later (`objdump -T`: the newest symbol version it needs, as README "FMI" says), holds no path of
// the machine that built it, the archive's files are stored -rw-r--r-- (`unzip -Z`), the model
// description has a version and one description per meaning (no two variables of an FMU share
// one; `phi` of the Environment and of the Controller each say theirs).
#include <gtest/gtest.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zip.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "fmi/export/fmu_export.hpp"
#include "fmi/fmu/model_description.hpp"
#include "spec/exploration/scenario.hpp"
#include "tests/fmi/scratch.hpp"
#include "tests/util/shell.hpp"

namespace {

namespace fs = std::filesystem;
using namespace swarmcheck;

struct Exported {
  std::string name;
  fmi::FmuSetup setup;
};

// s with the thesis preset's controller and body (`fmu export ... --preset thesis`).
exploration::Scenario intocps_preset(exploration::Scenario s) {
  s.controller = exploration::ControllerKind::thesis;
  s.body.kind = exploration::BodyKind::intocps;
  return s;
}

std::vector<Exported> every_fmu() {
  const exploration::Scenario s = exploration::default_scenario();
  return {{"environment", fmi::fmu_setup(fmi::Kind::environment, s)},
          {"controller", fmi::fmu_setup(fmi::Kind::controller, s)},
          {"body", fmi::fmu_setup(fmi::Kind::body, s)},
          {"thesis-environment", fmi::fmu_setup(fmi::Kind::environment, fmi::thesis_interface_scenario(), fmi::Interface::thesis)},
          {"thesis-controller", fmi::fmu_setup(fmi::Kind::controller, fmi::thesis_interface_scenario(), fmi::Interface::thesis)},
          {"thesis-body", fmi::fmu_setup(fmi::Kind::body, fmi::thesis_interface_scenario(), fmi::Interface::thesis)},
          {"intocps-body", fmi::fmu_setup(fmi::Kind::body, intocps_preset(s))},
          {"thesis-law-controller", fmi::fmu_setup(fmi::Kind::controller, intocps_preset(s))}};
}

std::string entry(const std::string& archive, const std::string& name) {
  int error = 0;
  zip_t* z = zip_open(archive.c_str(), ZIP_RDONLY, &error);
  EXPECT_NE(z, nullptr) << archive;
  if (!z) return {};
  zip_stat_t st;
  zip_stat_init(&st);
  std::string out;
  if (zip_stat(z, name.c_str(), 0, &st) == 0) {
    out.resize(st.size);
    zip_file_t* f = zip_fopen(z, name.c_str(), 0);
    zip_fread(f, out.data(), st.size);
    zip_fclose(f);
  }
  zip_close(z);
  return out;
}

// glibc's own libraries (and, in the sanitizer build, the sanitizers' runtimes and what they need).
bool allowed(const std::string& library) {
  static const std::set<std::string> glibc{"linux-vdso.so.1", "libc.so.6", "libm.so.6", "ld-linux-x86-64.so.2",
                                           "libpthread.so.0", "libdl.so.2", "librt.so.1"};
  if (glibc.count(library)) return true;
#ifdef SWARMCHECK_SANITIZE_BUILD
  for (const char* runtime : {"libasan.so", "libubsan.so", "libstdc++.so", "libgcc_s.so"})
    if (library.rfind(runtime, 0) == 0) return true;
#endif
  return false;
}

}  // namespace

TEST(FmiPortable, EveryExportedFmusLibraryNeedsOnlyGlibcAndItsFilesAreStoredAsReadableByAll) {
  const fs::path dir = swarmcheck::testing::fmi_scratch("portable");
  for (const Exported& e : every_fmu()) {
    const std::string fmu = (dir / (e.name + ".fmu")).string();
    fmi::write_fmu(e.setup, fmu);
    const std::string so = (dir / (e.name + ".so")).string();
    std::ofstream(so, std::ios::binary) << entry(fmu, "binaries/linux64/" + fmi::model_identifier(e.setup.kind) + ".so");
    const auto ldd = swarmcheck::testing::run_binary("ldd", so);
    ASSERT_EQ(ldd.status, 0) << ldd.out;
    std::istringstream lines(ldd.out);
    int libraries = 0;
    for (std::string line; std::getline(lines, line);) {
      std::istringstream words(line);
      std::string library;
      words >> library;
      library = fs::path(library).filename().string();   // "/lib64/ld-linux-x86-64.so.2 (0x...)"
      EXPECT_TRUE(allowed(library)) << e.name << " needs " << line;
      EXPECT_EQ(line.find("not found"), std::string::npos) << e.name << ": " << line;
      ++libraries;
    }
    EXPECT_GE(libraries, 2) << ldd.out;   // libc at least, and the loader
#ifndef SWARMCHECK_SANITIZE_BUILD
    // The oldest glibc it loads on (README "FMI"): the newest symbol version it needs, by objdump -T.
    const auto symbols = swarmcheck::testing::run_binary("objdump", "-T " + so);
    ASSERT_EQ(symbols.status, 0) << symbols.out;
    int newest = 0;   // minor version of GLIBC_2.x
    for (std::size_t at = symbols.out.find("GLIBC_2."); at != std::string::npos; at = symbols.out.find("GLIBC_2.", at + 1))
      newest = std::max(newest, std::atoi(symbols.out.c_str() + at + 8));
    EXPECT_EQ(newest, 35) << e.name << ": README \"FMI\" states glibc 2.35 as the floor";
#endif
    // unzip -Z: one line per entry, its Unix mode first.
    const auto listing = swarmcheck::testing::run_binary("unzip", "-Z " + fmu);
    ASSERT_EQ(listing.status, 0) << listing.out;
    int files = 0;
    std::istringstream entries(listing.out);
    for (std::string line; std::getline(entries, line);) {
      if (line.rfind("Archive:", 0) == 0 || line.find(" files, ") != std::string::npos || line.find("Zip file size") == 0) continue;
      EXPECT_EQ(line.rfind("-rw-r--r--", 0), 0u) << e.name << ": " << line;
      EXPECT_NE(line.find(" unx "), std::string::npos) << e.name << ": " << line;
      ++files;
    }
    EXPECT_EQ(files, 3) << listing.out;
  }
  fs::remove_all(dir);
}

TEST(FmiPortable, TheLibraryHoldsNoPathOfTheMachineThatBuiltIt) {
  const fs::path dir = swarmcheck::testing::fmi_scratch("paths");
  const std::string fmu = (dir / "e.fmu").string();
  fmi::write_fmu(every_fmu()[0].setup, fmu);
  const std::string bytes = entry(fmu, "binaries/linux64/swarmcheck_environment.so");
  ASSERT_GT(bytes.size(), 100000u);
  for (const std::string& path : {std::string(SWARMCHECK_SOURCE_DIR), std::string(SWARMCHECK_BINARY_DIR)})
    EXPECT_EQ(bytes.find(path), std::string::npos) << path << " is in the library";
  fs::remove_all(dir);
}

TEST(FmiPortable, EachModelDescriptionHasAVersionAndOneDescriptionPerMeaning) {
  std::map<std::string, std::map<std::string, std::string>> description_of;   // FMU -> variable -> description
  for (const Exported& e : every_fmu()) {
    const std::string xml = fmi::model_description_xml(e.setup, "9.9.9");
    const auto doc = std::unique_ptr<xmlDoc, void (*)(xmlDoc*)>(
        xmlReadMemory(xml.data(), static_cast<int>(xml.size()), "md.xml", nullptr, XML_PARSE_NONET), xmlFreeDoc);
    ASSERT_TRUE(doc);
    xmlNode* root = xmlDocGetRootElement(doc.get());
    xmlChar* version = xmlGetProp(root, reinterpret_cast<const xmlChar*>("version"));
    ASSERT_NE(version, nullptr) << e.name;
    EXPECT_STREQ(reinterpret_cast<const char*>(version), "9.9.9");
    xmlFree(version);
    std::map<std::string, std::string> used;   // description -> the variable that has it
    for (xmlNode* n = root->children; n; n = n->next) {
      if (n->type != XML_ELEMENT_NODE || xmlStrcmp(n->name, reinterpret_cast<const xmlChar*>("ModelVariables")) != 0) continue;
      for (xmlNode* v = n->children; v; v = v->next) {
        if (v->type != XML_ELEMENT_NODE) continue;
        xmlChar* name = xmlGetProp(v, reinterpret_cast<const xmlChar*>("name"));
        xmlChar* text = xmlGetProp(v, reinterpret_cast<const xmlChar*>("description"));
        const std::string variable = reinterpret_cast<const char*>(name);
        const std::string description = text ? reinterpret_cast<const char*>(text) : "";
        xmlFree(name);
        xmlFree(text);
        EXPECT_FALSE(description.empty()) << e.name << ": " << variable << " has no description";
        const auto [at, fresh] = used.emplace(description, variable);
        EXPECT_TRUE(fresh) << e.name << ": " << variable << " and " << at->second << " share \"" << description << "\"";
        description_of[e.name][variable] = description;
      }
    }
  }
  // A name in two FMUs with two meanings has two descriptions.
  for (const char* name : {"phi", "onDestinationOutput"})
    EXPECT_NE(description_of["environment"][name], description_of["controller"][name]) << name;
  EXPECT_NE(description_of["environment"]["phi"].find("pheromone"), std::string::npos);
  EXPECT_NE(description_of["controller"]["phi"].find("heading"), std::string::npos);
}
