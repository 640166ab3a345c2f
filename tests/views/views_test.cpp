// views/: field records, pictures, the generated schema, page assembly and the view readers.
#include <gtest/gtest.h>

#include <bit>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "conformance/exploration/engine.hpp"
#include "spec/exploration/domains.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"
#include "spec/exploration/trace_field.hpp"
#include "views/exploration_svg.hpp"
#include "views/fsm_svg.hpp"
#include "views/page.hpp"
#include "views/run_recorder.hpp"
#include "views/schema.hpp"
#include "views/view.hpp"

using namespace swarmcheck;
using namespace swarmcheck::exploration;
namespace cx = swarmcheck::conformance::exploration;

namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string write_temp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("swarmcheck-views-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(path) << text;
  return path.string();
}

}  // namespace

TEST(Base64, RoundTripsEveryLengthAndRefusesWhatIsNotBase64) {
  std::string bytes;
  for (int n = 0; n < 40; ++n) {
    EXPECT_EQ(base64_decode(base64_encode(bytes), "x"), bytes);
    bytes += static_cast<char>(n * 37);
  }
  EXPECT_EQ(base64_encode("Man"), "TWFu");
  EXPECT_EQ(base64_encode("Ma"), "TWE=");
  EXPECT_EQ(message_of([] { base64_decode("TWF", "f:3: pheromone"); }),
            "f:3: pheromone: expected base64 text (a multiple of 4 characters), got 3 characters");
  EXPECT_EQ(message_of([] { base64_decode("TW*u", "w"); }), "w: expected base64 text, got the character '*' at offset 2");
}

TEST(FieldRecord, CarriesEveryCellAsFloat32AndTheExactDigestOfTheStepRecord) {
  Scenario s = default_scenario();
  s.max_steps = 300;
  const auto sim = cx::make_simulation(cx::Engine::impl, s);
  while (!sim->done()) sim->step();
  const FieldSnapshot f = views::field_snapshot(*sim, s);
  const json_io::Json j = field_record(f);
  EXPECT_EQ(j["digest"].get<uint64_t>(), sim->record().pheromone_digest);   // the same FNV-1a
  const DecodedField d = decode_field_record(json_io::Json::parse(j.dump()), "t");
  ASSERT_EQ(d.pheromone.size(), 100u);
  int visited = 0;
  for (std::size_t k = 0; k < 100; ++k) {
    EXPECT_EQ(std::bit_cast<uint32_t>(d.pheromone[k]), std::bit_cast<uint32_t>(static_cast<float>(f.pheromone[k])));
    EXPECT_EQ(d.visited[k], f.visited[k]);
    visited += d.visited[k] ? 1 : 0;
  }
  EXPECT_EQ(visited, sim->visited());
  EXPECT_GT(d.pheromone_max, 0.0);
}

TEST(FieldRecord, AMalformedRecordIsBadInputNamingTheLine) {
  json_io::Json j = json_io::Json::parse(R"({"type":"field","step":1,"map_size":2,"encoding":"float32-le-base64",
      "pheromone":"AAAA","visited":"AA==","pheromone_max":0,"digest":1})");
  EXPECT_EQ(message_of([&] { decode_field_record(j, "t.jsonl:4"); }), "t.jsonl:4: the field's size does not match map_size 2");
  j.erase("digest");
  EXPECT_NE(message_of([&] { decode_field_record(j, "t.jsonl:4"); }).find("t.jsonl:4: expected a field record"), std::string::npos);
}

TEST(Schema, IsGeneratedFromTheDeclarationsAndTheDomainTable) {
  const json_io::Json schema = views::scenario_schema();
  EXPECT_EQ(schema["x-order"].get<std::vector<std::string>>(), json_io::field_names<Scenario>());
  EXPECT_EQ(schema["properties"]["params"]["x-order"].get<std::vector<std::string>>(), json_io::field_names<Params>());
  EXPECT_EQ(schema["properties"]["rule"]["enum"], json_io::Json::parse(R"(["thesis","deterministic","stochastic"])"));
  EXPECT_EQ(schema["properties"]["robots"]["items"]["minItems"], 2);
  for (const Domain& d : kScenarioDomains) {
    const std::string path(d.path);
    const auto dot = path.find('.');
    const json_io::Json& node = dot == std::string::npos ? schema["properties"][path]
                                                        : schema["properties"][path.substr(0, dot)]["properties"][path.substr(dot + 1)];
    EXPECT_EQ(node["x-expected"], std::string(d.expected)) << path;
    EXPECT_EQ(node["type"], d.integer ? "integer" : "number") << path;
  }
  // The table's texts state its bounds.
  EXPECT_EQ(kScenarioDomains[0].expected, "an integer in [1, " + std::to_string(kMapSizeMax) + "]");
  EXPECT_EQ(kScenarioDomains[2].expected, "an integer in [1, " + std::to_string(kRangeMax) + "]");
}

TEST(Page, IsSelfContainedAndDataCannotCloseItsScript) {
  views::Page p{"a </title><script>alert(1)</script>", {{"kind", "exploration"}, {"file", "</script><script>alert(2)</script>"}}};
  const std::string html = views::assemble_page(p);
  EXPECT_EQ(html.find("<script>alert"), std::string::npos);
  for (const char* fetch : {"src=\"http", "href=\"http", "url(http", "@import", "fetch('http", "<link"})
    EXPECT_EQ(html.find(fetch), std::string::npos) << fetch;   // (the SVG namespace URI is a name)
  EXPECT_NE(html.find("default-src 'none'"), std::string::npos);
  EXPECT_EQ(html.find("\nimport "), std::string::npos);   // the modules are inlined
  EXPECT_EQ(html.find("\nexport "), std::string::npos);
}

TEST(ExplorationSvg, DrawsEveryRobotAndBlocksBigMaps) {
  Scenario s = default_scenario();
  s.map_size = 300;
  s.robots = {{0.5, 0.5}, {150.5, 20.5}};
  s.obstacles.clear();
  views::ExplorationPicture p;
  p.scenario = s;
  p.field.map_size = 300;
  p.field.pheromone.assign(90000, 0.0);
  p.field.visited.assign(90000, false);
  p.field.pheromone[5] = 3.0;
  p.paths = {{{0.5, 0.5}, {1.5, 0.5}}, {{150.5, 20.5}}};
  p.poses = {BodyState{1.5, 0.5, 0.0}, BodyState{150.5, 20.5, 1.0}};
  const std::string svg = views::exploration_svg(p);
  std::size_t rects = 0;
  for (std::size_t at = svg.find("<rect"); at != std::string::npos; at = svg.find("<rect", at + 1)) ++rects;
  EXPECT_LT(rects, 128u * 128u);   // blocks of 3 x 3 cells, runs merged
  std::size_t robots = 0;
  for (std::size_t at = svg.find("class=\"robot\""); at != std::string::npos; at = svg.find("class=\"robot\"", at + 1)) ++robots;
  EXPECT_EQ(robots, 2u);
}

TEST(ViewReaders, BadFilesGetOneMessageNamingFileAndLine) {
  const views::ViewOptions o;
  const std::string header = trace_header(default_scenario()).dump();
  auto msg = [&](const std::string& name, const std::string& text) {
    const std::string path = write_temp(name, text);
    return message_of([&] { views::view_page(path, o); }).substr(path.size());
  };
  EXPECT_EQ(msg("empty", ""), ": empty file: expected a trace or an .fsm automaton");
  EXPECT_EQ(msg("nojson", "{oops\n").rfind(":1:2: not valid JSON: syntax error", 0), 0U);
  EXPECT_NE(msg("other", "{\"format\": \"csv\"}\n").find(":1: expected a trace header"), std::string::npos);
  EXPECT_EQ(msg("norecords", header + "\n"), ": the trace has a header but no step record");
  EXPECT_EQ(msg("badrecord", header + "\n{\"step\": \"x\"}\n"), ":2: expected a step record: step: expected an integer, got a string");
  EXPECT_EQ(msg("badline", header + "\n{\n").rfind(":2:2: not valid JSON: syntax error", 0), 0U);
  EXPECT_NE(msg("fsm", "2\n\ns1 0 1\na s9 c o\n").find(":"), std::string::npos);   // the .fsm reader's message
  EXPECT_EQ(message_of([&] { views::view_page("/nonexistent/t.jsonl", o); }), "/nonexistent/t.jsonl: cannot open the file to view: no such file");
}

// dot gets a time limit: a dense automaton under the transition cap kept it busy for hours (and a
// server's worker with it). Past the limit dot is killed and the layout is nullopt; within it, a
// small automaton is laid out.
TEST(FsmSvg, DotIsKilledPastItsTimeLimitAndASmallAutomatonIsStillLaidOut) {
  if (!swarmcheck::views::dot_available()) GTEST_SKIP() << "graphviz's dot is not installed";
  swarmcheck::supervisor::Automaton dense;
  const int n = 63;
  for (int i = 0; i < n; ++i) dense.states.push_back("s" + std::to_string(i));
  for (int j = 0; j < n; ++j) dense.events["e" + std::to_string(j)] = {};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) dense.delta["s" + std::to_string(i)]["e" + std::to_string(j)] = "s" + std::to_string((i * 7 + j * 13) % n);
  // (Not killed, this would wait for dot for hours: the test's own timeout would fail it.)
  EXPECT_FALSE(swarmcheck::views::fsm_svg_within(dense, std::chrono::milliseconds(300)).has_value());
  swarmcheck::supervisor::Automaton small;
  small.states = {"a", "b"};
  small.events["go"] = {};
  small.delta["a"]["go"] = "b";
  const auto svg = swarmcheck::views::fsm_svg_within(small, std::chrono::seconds(60));
  ASSERT_TRUE(svg.has_value());
  EXPECT_EQ(svg->rfind("<svg", 0), 0U);
}
