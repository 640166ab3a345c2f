// parse_json_text (spec/util/json_text.hpp) builds its document with its own SAX handler, which
// appends each object member instead of looking its key up (ordered_json's lookup is linear: an
// object of N keys took O(N^2)). It must build exactly what nlohmann's own parser builds.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "spec/util/json_text.hpp"

namespace {

using swarmcheck::json_io::Json;

// One seed for every run (an RC_PARAMS in the environment wins).
const bool kSeededJsonTextTest = [] { return ::setenv("RC_PARAMS", "seed=23", 0) == 0; }();

rc::Gen<Json> gen_scalar() {
  return rc::gen::oneOf(rc::gen::just(Json(nullptr)), rc::gen::map(rc::gen::arbitrary<bool>(), [](bool b) { return Json(b); }),
                        rc::gen::map(rc::gen::arbitrary<int64_t>(), [](int64_t v) { return Json(v); }),
                        rc::gen::map(rc::gen::arbitrary<uint64_t>(), [](uint64_t v) { return Json(v); }),
                        rc::gen::map(rc::gen::arbitrary<double>(),
                                     [](double v) { return std::isfinite(v) ? Json(v) : Json(0.5); }),
                        rc::gen::map(rc::gen::arbitrary<std::string>(), [](std::string v) {
                          // JSON text is UTF-8: keep the ASCII of arbitrary bytes.
                          for (char& c : v) c = static_cast<char>(static_cast<unsigned char>(c) & 0x7f);
                          return Json(v);
                        }));
}

rc::Gen<Json> gen_json(int depth) {
  if (depth == 0) return gen_scalar();
  const auto inner = rc::gen::lazy([depth] { return gen_json(depth - 1); });
  const auto array = rc::gen::map(rc::gen::container<std::vector<Json>>(inner), [](std::vector<Json> xs) {
    Json a = Json::array();
    for (auto& x : xs) a.push_back(std::move(x));
    return a;
  });
  const auto object = rc::gen::map(
      rc::gen::container<std::vector<std::pair<std::string, Json>>>(
          rc::gen::pair(rc::gen::map(rc::gen::inRange(0, 40), [](int k) { return "k" + std::to_string(k); }), inner)),
      [](std::vector<std::pair<std::string, Json>> members) {
        Json o = Json::object();
        std::set<std::string> seen;   // unique keys, in the generated order
        for (auto& [k, v] : members)
          if (seen.insert(k).second) o[k] = std::move(v);
        return o;
      });
  return rc::gen::oneOf(gen_scalar(), array, object);
}

}  // namespace

RC_GTEST_PROP(JsonText, TheAppendingParserBuildsWhatNlohmannsParserBuildsForAnyDocument, ()) {
  const Json doc = *gen_json(3);
  const std::string text = *rc::gen::element(doc.dump(), doc.dump(2), doc.dump(-1, ' ', true));
  const Json ours = swarmcheck::json_io::parse_json_text(text, "t.json");
  const Json theirs = Json::parse(text);
  RC_ASSERT(ours == theirs);
  RC_ASSERT(ours.dump() == theirs.dump());   // the same members in the same order, the same number types
}

TEST(JsonText, AnObjectOfAHundredThousandKeysKeepsThemInFileOrder) {
  std::string text = "{";
  for (int k = 99999; k >= 0; --k) text += (k == 99999 ? "\"" : ",\"") + std::to_string(k) + "\":" + std::to_string(k);
  text += "}";
  const Json j = swarmcheck::json_io::parse_json_text(text, "t.json");
  ASSERT_EQ(j.size(), 100000U);
  EXPECT_EQ(j.begin().key(), "99999");
  EXPECT_EQ(j["0"], 0);
  int expected = 99999;   // (nlohmann's own parser would take minutes to compare with)
  for (const auto& [key, value] : j.items()) {
    ASSERT_EQ(key, std::to_string(expected));
    ASSERT_EQ(value, expected);
    --expected;
  }
}

TEST(JsonText, SyntaxErrorsAndNumbersOutOfRangeAreReportedAsBefore) {
  const auto error_of = [](const std::string& text) {
    try {
      swarmcheck::json_io::parse_json_text(text, "t.json");
    } catch (const swarmcheck::InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_of("{\"a\": [1, 2,]}"), "t.json:1:13: not valid JSON: syntax error while parsing value - unexpected ']'; expected '[', '{', or a literal");
  EXPECT_EQ(error_of("{\"a\": 1e400}"), "t.json:1:7: a number outside the range of a double (1e400)");
  EXPECT_EQ(error_of("{\"a\": 1, \"a\": 2}"), "t.json:1:10: the key \"a\" appears twice in one object (each key once)");
  EXPECT_EQ(error_of("[1] x"), "t.json:1:5: not valid JSON: syntax error while parsing value - invalid literal; last read: '1] x'; expected end of input");
}
