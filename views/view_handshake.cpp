// The proof counterexample view: a handshake trace (`prove --trace-dir`) as a table, step by step.
// `swarmcheck view` checks the file with proofs/' reader first (views/ may not include proofs/);
// the shape the page needs is checked here too, for traces posted to `serve`.
#include <fmt/format.h>

#include "spec/util/input_error.hpp"
#include "views/view.hpp"

namespace swarmcheck::views {
namespace {

using json_io::Json;

void require_step_shape(const Json& j, std::size_t robots, const std::string& where) {
  auto integer = [&](const Json& o, const char* key) { return o.contains(key) && o[key].is_number_integer(); };
  auto boolean = [&](const Json& o, const char* key) { return o.contains(key) && o[key].is_boolean(); };
  const bool ok = j.is_object() && integer(j, "step") && integer(j, "flag") && integer(j, "onDestinationOutput") &&
                  boolean(j, "plan") && j.contains("controllers") && j["controllers"].is_array() &&
                  j["controllers"].size() == robots;
  if (!ok)
    throw InputError(where, fmt::format("expected a step {{\"step\", \"flag\", \"onDestinationOutput\", \"plan\", "
                                        "\"controllers\": {} objects}}", robots));
  for (const Json& c : j["controllers"])
    if (!(c.is_object() && integer(c, "onDestinationOutput") && boolean(c, "arrival") && boolean(c, "accepted") && boolean(c, "reached")))
      throw InputError(where, "expected each controller as {\"onDestinationOutput\", \"arrival\", \"accepted\", \"reached\"}");
  if (j.contains("violated") && !j["violated"].is_string()) throw InputError(where, "\"violated\" must be a string");
}

}  // namespace

Page handshake_page(const std::string& text, const std::string& path) {
  const std::vector<JsonLine> lines = json_lines(text, path);
  const Json& header = lines.front().json;
  if (!header.contains("robots") || !header["robots"].is_number_integer() || header["robots"].get<int64_t>() < 1 ||
      header["robots"].get<int64_t>() > 4096)
    throw InputError(path + ":" + std::to_string(lines.front().number), "expected \"robots\": an integer in [1, 4096]");
  const auto robots = header["robots"].get<std::size_t>();
  Json steps = Json::array();
  for (std::size_t k = 1; k < lines.size(); ++k) {
    require_step_shape(lines[k].json, robots, path + ":" + std::to_string(lines[k].number));
    steps.push_back(lines[k].json);
  }
  Json data = {{"kind", "handshake"}, {"file", path}, {"header", header}, {"steps", steps}};
  return Page{"swarmcheck proof counterexample: " + path, data};
}

}  // namespace swarmcheck::views
