// Event attributes pooled across the files of one command (spec/supervisor/attributes.hpp): what
// the reader reports a file states, and where; unstated attributes taken from another file; a
// conflict naming both places; the compact reader and the value reader agreeing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "impl/supervisor/fsm_compact_io.hpp"
#include "impl/supervisor/fsm_io.hpp"
#include "swarmcheck/supervisor.hpp"

namespace {

namespace sv = swarmcheck::supervisor;
namespace impl = swarmcheck::impl::supervisor;
namespace fs = std::filesystem;

std::string file_with(const std::string& name, const std::string& text) {
  const fs::path d = fs::temp_directory_path() / ("swarmcheck_attr_" + std::to_string(::getpid()));
  fs::create_directories(d);
  std::ofstream(d / name) << text;
  return (d / name).string();
}

TEST(EventAttributes, TheReaderReportsWhatAFileStatesAndWhere) {
  sv::Statements st;
  impl::read_fsm_compact("2\nx 0 2\na y uc\nb y\ny 1 1\na x uc o\nEVENTS\nz c\n", "f.fsm", &st);
  ASSERT_EQ(st.size(), 3u);
  EXPECT_EQ(st.at("a").controllable, (sv::Stated{false, "f.fsm:3:5"}));
  EXPECT_EQ(st.at("a").observable, (sv::Stated{true, "f.fsm:6:8"}));
  EXPECT_FALSE(st.at("b").controllable.has_value());
  EXPECT_FALSE(st.at("b").observable.has_value());
  EXPECT_EQ(st.at("z").controllable, (sv::Stated{true, "f.fsm:8:3"}));
}

TEST(EventAttributes, UnstatedAttributesComeFromTheFileThatStatesThem) {
  const auto attrs = sv::resolve_attributes(
      {{{"u", {sv::Stated{false, "p.fsm:3:5"}, std::nullopt}}},
       {{"u", {std::nullopt, sv::Stated{false, "s.fsm:4:7"}}}, {"v", {}}}});
  EXPECT_EQ(attrs.at("u"), (sv::EventAttr{false, false}));
  EXPECT_EQ(attrs.at("v"), (sv::EventAttr{true, true}));   // stated nowhere: c, o
}

TEST(EventAttributes, AConflictNamesBothPlaces) {
  try {
    sv::resolve_attributes({{{"u", {sv::Stated{false, "p.fsm:3:5"}, std::nullopt}}},
                            {{"u", {sv::Stated{true, "s.fsm:9:2"}, std::nullopt}}}});
    FAIL() << "no error";
  } catch (const swarmcheck::InputError& e) {
    EXPECT_STREQ(e.what(), "s.fsm:9:2: event 'u' is c here but uc at p.fsm:3:5");
  }
}

TEST(EventAttributes, CompactAndValueReadersOfOneCommandAgree) {
  const std::string plant = file_with("p.fsm", "2\np0 0 1\nu p1 uc uo\np1 1 1\na p0 c\n");
  const std::string spec = file_with("s.fsm", "2\ns0 0 1\nu s1\ns1 1 1\na s0 c uo\n");
  const auto values = sv::read_fsm_files({plant, spec});
  const auto compact = impl::read_fsm_compact_files({plant, spec});
  ASSERT_EQ(values.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(impl::decompile(compact[i]), values[i]);
  EXPECT_EQ(values[1].events.at("u"), (sv::EventAttr{false, false}));
  EXPECT_EQ(values[0].events.at("a"), (sv::EventAttr{true, false}));
  // Read alone, each file keeps the UMDES defaults for what it leaves out.
  EXPECT_EQ(sv::read_fsm_file(spec).events.at("u"), (sv::EventAttr{true, true}));
}

}  // namespace
