// The scenario reader's fast path (spec/util/json_pair_lists.hpp) against the whole-DOM reader:
// the same scenario, bit for bit, or the same message, for any text.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "spec/exploration/scenario.hpp"
#include "spec/util/hana_json.hpp"

using namespace swarmcheck;
using namespace swarmcheck::exploration;

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededExplorationScenarioReaderTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();

// What a reader makes of a text: the scenario's JSON and its robots' bits, or the message.
std::string outcome(Scenario (*read)(const std::string&, const std::string&), const std::string& text) {
  try {
    const Scenario s = read(text, "s.json");
    std::string bits;
    for (const Point_m& p : s.robots) {
      char b[sizeof p];
      std::memcpy(b, p.data(), sizeof p);
      bits.append(b, sizeof p);
    }
    return json_io::to_json(s).dump() + "|" + bits;
  } catch (const InputError& e) {
    return std::string("error: ") + e.what();
  }
}

void expect_same_as_dom(const std::string& text) {
  EXPECT_EQ(outcome(parse_scenario, text), outcome(parse_scenario_dom, text)) << text;
}

// A number as a user might write it: integer, decimal, exponent, signed zero, padded.
std::string gen_number_text(int32_t whole_max) {
  const int32_t whole = *rc::gen::inRange(0, whole_max);
  switch (*rc::gen::inRange(0, 6)) {
    case 0: return std::to_string(whole);
    case 1: return std::to_string(whole) + ".5";
    case 2: return std::to_string(whole) + "5e-1";
    case 3: return *rc::gen::element<std::string>("-0", "-0.0", "0e0", "0.0", "-1", "1E+0");
    case 4: return std::to_string(whole) + "." + std::to_string(*rc::gen::inRange(0, 1000000));
    default: return " " + std::to_string(whole) + ".25\n";
  }
}

// A scenario text with a few robots and obstacles, members in any order, odd spacing.
std::string gen_scenario_text() {
  const int32_t n = *rc::gen::inRange(2, 9);
  std::vector<std::string> members;
  members.push_back("\"map_size\": " + std::to_string(n));
  std::string robots = "\"robots\":[";
  const int32_t count = *rc::gen::inRange(0, 5);
  for (int32_t k = 0; k < count; ++k)
    robots += (k ? ", " : "") + std::string("[") + gen_number_text(n) + "," + gen_number_text(n) + "]";
  members.push_back(robots + "]");
  if (*rc::gen::arbitrary<bool>()) {
    std::string obstacles = "\"obstacles\": [ ";
    const int32_t m = *rc::gen::inRange(0, 4);
    for (int32_t k = 0; k < m; ++k)
      obstacles += (k ? " ,\r\n" : "") + std::string("[") + std::to_string(*rc::gen::inRange(-1, n + 1)) + ", " +
                   std::to_string(*rc::gen::inRange(0, n)) + "]";
    members.push_back(obstacles + "]");
  }
  if (*rc::gen::arbitrary<bool>()) members.push_back("\"params\": {\"s_range\": 1, \"a1\": 0.5}");
  if (*rc::gen::arbitrary<bool>()) members.push_back("\"mode\": \"abstract\"");
  std::vector<std::string> order = members;
  for (std::size_t k = order.size() - 1; k > 0; --k)   // a drawn permutation
    std::swap(order[k], order[*rc::gen::inRange<std::size_t>(0, k + 1)]);
  std::string text = "{";
  for (std::size_t k = 0; k < order.size(); ++k) text += (k ? ",\n " : "") + order[k];
  return text + "}";
}

// One edit that JSON cares about: a structural character, a quote, a digit, a sign, a letter.
std::string mutate(std::string text) {
  const auto at = static_cast<std::size_t>(*rc::gen::inRange<std::size_t>(0, text.size() + 1));
  const char c = *rc::gen::element('[', ']', '{', '}', ',', ':', '"', '\\', '-', '.', 'e', '0', '7', ' ', 'x');
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return text.insert(at, 1, c);
    case 1: return at < text.size() ? text.erase(at, 1) : text;
    default: return at < text.size() ? text.replace(at, 1, 1, c) : text;
  }
}

}  // namespace

RC_GTEST_PROP(ScenarioReader, GivesTheDomReadersScenarioBitForBitOrItsExactMessageForAnyMutatedText, ()) {
  std::string text = gen_scenario_text();
  const int32_t edits = *rc::gen::inRange(0, 4);
  for (int32_t k = 0; k < edits; ++k) text = mutate(text);
  const std::string dom = outcome(parse_scenario_dom, text);
  RC_TAG(dom.starts_with("error: s.json: ") ? "error at a JSON path" : dom.starts_with("error") ? "syntax error" : "read");
  RC_ASSERT(outcome(parse_scenario, text) == dom);
}

TEST(ScenarioReader, ReadsNumbersAsTheDomReaderDoes) {
  // Integer literals are integers first (so -0 is +0.0); -0.0 keeps its sign.
  for (const char* robot : {"[-0, 0.5]", "[-0.0, 0.5]", "[1e0, 5E-1]", "[1, 0.50000000000000001]",
                            "[0.1, 2.675]", "[3.9999999999999999, 0.5]"})
    expect_same_as_dom(std::string(R"({"map_size": 4, "robots": [)") + robot + "]}");
  const Scenario minus_zero = parse_scenario(R"({"map_size": 4, "robots": [[-0, 0.5]]})", "s.json");
  EXPECT_FALSE(std::signbit(minus_zero.robots[0][0]));
}

TEST(ScenarioReader, LeavesEveryUnusualListToTheDomReaderWithItsMessage) {
  const std::string head = R"({"map_size": 4, )";
  for (const char* tail : {
           R"("robots": [[0.5, 0.5, 0.5]]})", R"("robots": [[0.5]]})", R"("robots": [0.5, 0.5]})",
           R"("robots": [[0.5, "0.5"]]})", R"("robots": {"a": 1}})", R"("robots": [[1e400, 0.5]]})",
           R"("robots": [[1e-400, 0.5]]})", R"("robots": [[12345678901234567890, 0.5]]})",
           R"("robots": [[99999999999999999999999, 0.5]]})", R"("robots": [[01, 0.5]]})",
           R"("robots": [[.5, 0.5]]})", R"("robots": [[0.5, 0.5],]})", R"("robots": [[0.5, 0.5]] "x": 1})",
           R"("robots": [[0.5, 0.5]], "robots": [[1.5, 1.5]]})", R"("rob\u006fts": [[0.5, 0.5]]})",
           R"("robots": [[0.5, 0.5]], "rob\u006fts": [[1.5, 1.5]]})", R"("robots": [[0.5, 0.5]]} trailing)",
           R"("robots": [[0.5, 0.5]], "obstacles": [[1.0, 2]]})", R"("robots": [[0.5, 0.5]], "obstacles": [[3000000000, 2]]})",
           R"("robots": [[0.5, 0.5]], "obstacles": [[-1, 2]]})", R"("robots": [[0.5, 0.5]], "obstacles": [[2, 2], [2, 2]]})",
           R"("robots": [[0.5, 0.5]], "params": {"robots": [[1, 2]]}})", R"("x": "}\"", "robots": [[0.5, 0.5]]})",
           R"("robots": [[0.5, 0.5]], "map_size": 5})", R"("robots": [[NaN, 0.5]]})", R"("robots": [[-, 0.5]]})",
           R"("robots": [[0.5, 0.5]])", R"("robots": [[0.5, 0.5]], "obstacles": []})"}) {
    expect_same_as_dom(head + tail);
  }
  EXPECT_EQ(outcome(parse_scenario, head + R"("robots": [[1e400, 0.5]]})"),
            "error: s.json:1:29: a number outside the range of a double (1e400)");
}

TEST(ScenarioReader, ValidScenarioIsOnlyEverAValidatedOne) {
  Scenario bad = default_scenario();
  bad.robots.push_back(bad.robots.front());
  EXPECT_THROW(ValidScenario{bad}, InputError);
  const ValidScenario good = parse_valid_scenario(R"({"map_size": 4, "robots": [[0.5, 0.5]]})", "s.json");
  EXPECT_EQ(good.get().robots.size(), 1u);
  EXPECT_EQ(json_io::to_json(std::move(ValidScenario(default_scenario())).release()), json_io::to_json(default_scenario()));
}
