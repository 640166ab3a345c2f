// Unpacking an FMU (fmi/master/fmu_library.cpp) refuses an archive that unpacks to more than its
// limit (1 GiB by default) before writing it, and leaves no temporary folder: a small zip of zeros
// must not fill the disk before anything looks at it.
#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "fmi/master/fmu_library.hpp"
#include "spec/util/input_error.hpp"
#include "tests/fmi/scratch.hpp"

namespace {

namespace fs = std::filesystem;

// A zip source of `left` zero bytes, made as it is read (nothing of that size is ever held).
struct Zeros {
  std::uint64_t left;
};
zip_int64_t zeros(void* state, void* data, zip_uint64_t len, zip_source_cmd_t cmd) {
  auto* z = static_cast<Zeros*>(state);
  switch (cmd) {
    case ZIP_SOURCE_OPEN:
    case ZIP_SOURCE_CLOSE: return 0;
    case ZIP_SOURCE_READ: {
      const zip_uint64_t n = std::min<zip_uint64_t>(len, z->left);
      std::memset(data, 0, n);
      z->left -= n;
      return static_cast<zip_int64_t>(n);
    }
    case ZIP_SOURCE_STAT: {
      auto* st = static_cast<zip_stat_t*>(data);
      zip_stat_init(st);
      return sizeof(zip_stat_t);
    }
    case ZIP_SOURCE_ERROR: return 2 * sizeof(int);
    case ZIP_SOURCE_FREE: return 0;
    case ZIP_SOURCE_SUPPORTS:
      return zip_source_make_command_bitmap(ZIP_SOURCE_OPEN, ZIP_SOURCE_READ, ZIP_SOURCE_CLOSE, ZIP_SOURCE_STAT,
                                            ZIP_SOURCE_ERROR, ZIP_SOURCE_FREE, -1);
    default: return -1;
  }
}

std::size_t temp_folders(const fs::path& tmp) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(tmp))
    if (e.path().filename().string().rfind("swarmcheck-fmu-", 0) == 0) ++n;
  return n;
}

// An archive made of modelDescription.xml and `zeros` bytes of zeros (deflated: a few KB).
std::string zip_of_zeros(const fs::path& dir, std::uint64_t zeros_bytes, Zeros& z) {
  const std::string fmu = (dir / "bomb.fmu").string();
  int error = 0;
  zip_t* za = zip_open(fmu.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (!za) return "";
  static const char xml[] = "<fmiModelDescription/>";
  zip_file_add(za, "modelDescription.xml", zip_source_buffer(za, xml, std::strlen(xml), 0), ZIP_FL_OVERWRITE);
  z.left = zeros_bytes;
  const zip_int64_t k = zip_file_add(za, "resources/zeros.bin", zip_source_function(za, zeros, &z), ZIP_FL_OVERWRITE);
  if (k < 0) return "";
  zip_set_file_compression(za, static_cast<zip_uint64_t>(k), ZIP_CM_DEFLATE, 9);
  return zip_close(za) == 0 ? fmu : "";
}

TEST(FmuUnpack, AnArchiveThatUnpacksToMoreThanTheLimitIsRefusedBeforeWritingAndLeavesNoTemporaryFolder) {
  const fs::path dir = swarmcheck::testing::fmi_scratch("unpack");
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
  ::setenv("TMPDIR", tmp.c_str(), 1);   // FmuLibrary unpacks under $TMPDIR
  Zeros z{0};
  const std::string fmu = zip_of_zeros(dir, std::uint64_t{64} << 20, z);   // 64 MiB of zeros
  ASSERT_FALSE(fmu.empty());
  EXPECT_LT(fs::file_size(fmu), std::uintmax_t{1} << 20);
  try {
    swarmcheck::fmi::master::FmuLibrary lib(fmu, std::uint64_t{16} << 20);   // a 16 MiB limit
    ADD_FAILURE() << "loaded";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unpacks to more than 16.0 MiB: refused as a zip bomb (by the sizes it declares)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(temp_folders(tmp), 0U);
  // The default limit is 1 GiB: the same archive passes the size check (and fails later, as it
  // is no FMU: its modelDescription.xml is empty of variables and it has no binary).
  try {
    swarmcheck::fmi::master::FmuLibrary lib(fmu);
    ADD_FAILURE() << "loaded";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("zip bomb"), std::string::npos) << e.what();
  }
  EXPECT_EQ(temp_folders(tmp), 0U);
  ::unsetenv("TMPDIR");
  fs::remove(fmu);
}

// An archive of the given entries (name, text); a name ending in '/' is a folder.
std::string zip_of(const fs::path& fmu, const std::vector<std::pair<std::string, std::string>>& entries) {
  int error = 0;
  zip_t* za = zip_open(fmu.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  if (!za) return "";
  for (const auto& [name, text] : entries) {
    if (name.back() == '/') zip_dir_add(za, name.substr(0, name.size() - 1).c_str(), ZIP_FL_ENC_UTF_8);
    else zip_file_add(za, name.c_str(), zip_source_buffer(za, text.data(), text.size(), 0), ZIP_FL_OVERWRITE);
  }
  return zip_close(za) == 0 ? fmu.string() : "";
}

std::string load_error(const std::string& fmu) {
  try {
    swarmcheck::fmi::master::FmuLibrary lib(fmu);
  } catch (const swarmcheck::InputError& e) {
    return e.what();
  }
  return "(loaded)";
}

// Archives no FMU tool writes are bad input (status 2) naming the FMU, never an internal error:
// a file where a folder is needed, modelDescription.xml a folder, XML errors on one line.
TEST(FmuUnpack, ArchivesWithClashingEntriesOrAFolderForTheModelDescriptionAreInputErrors) {
  const fs::path dir = swarmcheck::testing::fmi_scratch("unpack-clash");
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
  ::setenv("TMPDIR", tmp.c_str(), 1);
  const std::string xml = "<fmiModelDescription/>";
  const std::string clash = zip_of(dir / "clash.fmu", {{"modelDescription.xml", xml}, {"binaries", "x"}, {"binaries/linux64/m.so", "y"}});
  ASSERT_FALSE(clash.empty());
  EXPECT_EQ(load_error(clash), clash + ": archive entry 'binaries/linux64/m.so' clashes with an earlier entry (a file and a folder of one name)");
  const std::string folder = zip_of(dir / "folder.fmu", {{"modelDescription.xml/", ""}, {"modelDescription.xml/x", "y"}});
  ASSERT_FALSE(folder.empty());
  EXPECT_EQ(load_error(folder), folder + ": the archive has no modelDescription.xml file at its top");
  const std::string broken = zip_of(dir / "broken.fmu", {{"modelDescription.xml", "<fmiModelDescription><a>"}});
  ASSERT_FALSE(broken.empty());
  const std::string message = load_error(broken);
  EXPECT_NE(message.find("modelDescription.xml is not well-formed XML: "), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(load_error(dir.string()), dir.string() + ": expected an FMU file, got a folder or a device");
  EXPECT_EQ(temp_folders(tmp), 0U);
  ::unsetenv("TMPDIR");
}

}  // namespace
