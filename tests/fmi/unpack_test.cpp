// Unpacking an FMU (fmi/master/fmu_library.cpp) refuses an archive that unpacks to more than
// 1 GiB, as it reads it, and leaves no temporary folder: a small zip of zeros must not fill the
// disk before anything looks at it.
#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

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

TEST(FmuUnpack, AnArchiveThatUnpacksToMoreThanOneGibIsRefusedAndLeavesNoTemporaryFolder) {
  const fs::path dir = swarmcheck::testing::fmi_scratch("unpack");
  const fs::path tmp = dir / "tmp";
  fs::create_directories(tmp);
  ::setenv("TMPDIR", tmp.c_str(), 1);   // FmuLibrary unpacks under $TMPDIR
  const std::string fmu = (dir / "bomb.fmu").string();
  int error = 0;
  zip_t* za = zip_open(fmu.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(za, nullptr);
  const char xml[] = "<fmiModelDescription/>";
  zip_file_add(za, "modelDescription.xml", zip_source_buffer(za, xml, std::strlen(xml), 0), ZIP_FL_OVERWRITE);
  Zeros z{(std::uint64_t{1} << 30) + (std::uint64_t{1} << 20)};
  const zip_int64_t k = zip_file_add(za, "resources/zeros.bin", zip_source_function(za, zeros, &z), ZIP_FL_OVERWRITE);
  ASSERT_GE(k, 0);
  zip_set_file_compression(za, static_cast<zip_uint64_t>(k), ZIP_CM_DEFLATE, 1);
  ASSERT_EQ(zip_close(za), 0);
  EXPECT_LT(fs::file_size(fmu), std::uintmax_t{16} << 20);   // a few MB on disk
  try {
    swarmcheck::fmi::master::FmuLibrary lib(fmu);
    ADD_FAILURE() << "loaded";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unpacks to more than 1 GiB (at archive entry 'resources/zeros.bin')"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(temp_folders(tmp), 0U);
  ::unsetenv("TMPDIR");
  fs::remove(fmu);
}

}  // namespace
