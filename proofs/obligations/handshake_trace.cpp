#include "proofs/obligations/handshake_trace.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/json_text.hpp"

namespace swarmcheck::proofs::handshake {
namespace {

using Json = nlohmann::ordered_json;

// A field of one trace line, with a message that names the line when it is missing or wrong.
class Line {
 public:
  Line(const std::string& path, int number, const std::string& text) : where_(fmt::format("{}:{}", path, number)) {
    j_ = json_io::parse_json_text(text, path, number);   // file:line:col, nesting, repeated keys
    if (!j_.is_object()) throw InputError(where_, "expected a JSON object");
  }
  const std::string& where() const { return where_; }
  const Json& at(const Json& obj, const char* key, const char* what) const {
    if (!obj.is_object() || !obj.contains(key)) throw InputError(where_, fmt::format("missing \"{}\" ({})", key, what));
    return obj[key];
  }
  int64_t integer(const Json& obj, const char* key, int64_t lo, int64_t hi) const {
    const Json& v = at(obj, key, "an integer");
    if (!v.is_number_integer() || v.get<int64_t>() < lo || v.get<int64_t>() > hi)
      throw InputError(where_, fmt::format("\"{}\" must be an integer in [{}, {}]", key, lo, hi));
    return v.get<int64_t>();
  }
  bool boolean(const Json& obj, const char* key) const {
    const Json& v = at(obj, key, "true or false");
    if (!v.is_boolean()) throw InputError(where_, fmt::format("\"{}\" must be true or false", key));
    return v.get<bool>();
  }
  std::string string(const Json& obj, const char* key) const {
    const Json& v = at(obj, key, "a string");
    if (!v.is_string()) throw InputError(where_, fmt::format("\"{}\" must be a string", key));
    return v.get<std::string>();
  }
  // An optional finite number (traces written before poses were recorded lack them).
  double number_or(const Json& obj, const char* key, double fallback) const {
    if (!obj.is_object() || !obj.contains(key)) return fallback;
    const Json& v = obj[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw InputError(where_, fmt::format("\"{}\" must be a finite number", key));
    return v.get<double>();
  }
  const Json& json() const { return j_; }

 private:
  std::string where_;
  Json j_;
};

void read_header(const Line& l, HandshakeTrace& t) {
  const Json& j = l.json();
  if (l.string(j, "format") != "swarmcheck-trace") throw InputError(l.where(), "\"format\" must be \"swarmcheck-trace\"");
  if (l.integer(j, "format_version", 0, 1000) != 1) throw InputError(l.where(), "unsupported format_version (expected 1)");
  if (l.string(j, "system") != "handshake") throw InputError(l.where(), "\"system\" must be \"handshake\"");
  t.obligation = l.string(j, "obligation");
  t.robots = static_cast<int32_t>(l.integer(j, "robots", 1, 1 << 20));
  t.master = l.string(j, "master");
  if (t.master != "jacobi" && t.master != "gauss-seidel")
    throw InputError(l.where(), "\"master\" must be \"jacobi\" or \"gauss-seidel\"");
  t.controller = j.contains("controller") ? l.string(j, "controller") : "spec";
  if (t.controller != "spec" && t.controller != "late")
    throw InputError(l.where(), "\"controller\" must be \"spec\" or \"late\"");
  t.tolerance_m = l.number_or(j, "tolerance", t.tolerance_m);
  t.orient_tolerance_rad = l.number_or(j, "orient_tolerance", t.orient_tolerance_rad);
  t.reorient_rad = l.number_or(j, "reorient", t.reorient_rad);
  for (const auto& [key, value] : {std::pair{"tolerance", t.tolerance_m}, std::pair{"orient_tolerance", t.orient_tolerance_rad},
                                   std::pair{"reorient", t.reorient_rad}})
    if (!(value >= 0)) throw InputError(l.where(), fmt::format("\"{}\" must be a number >= 0", key));
}

TraceStep read_step(const Line& l, const HandshakeTrace& t, int64_t expected_step) {
  const Json& j = l.json();
  TraceStep s;
  s.step = l.integer(j, "step", 0, INT64_MAX);
  if (s.step != expected_step) throw InputError(l.where(), fmt::format("expected step {}", expected_step));
  s.flag = static_cast<int32_t>(l.integer(j, "flag", 0, 1));
  s.on_destination_output = static_cast<int32_t>(l.integer(j, "onDestinationOutput", 0, 1));
  s.plan = l.boolean(j, "plan");
  const Json& cs = l.at(j, "controllers", "an array with one object per robot");
  if (!cs.is_array() || cs.size() != static_cast<std::size_t>(t.robots))
    throw InputError(l.where(), fmt::format("\"controllers\" must be an array of {} objects (robots)", t.robots));
  for (const Json& c : cs)
    s.controllers.push_back(TraceController{static_cast<int32_t>(l.integer(c, "onDestinationOutput", 0, 1)),
                                            l.boolean(c, "arrival"), l.boolean(c, "accepted"),
                                            l.boolean(c, "reached"), l.number_or(c, "x", 0),
                                            l.number_or(c, "y", 0), l.number_or(c, "theta", 0),
                                            l.number_or(c, "xDesired", 0.5), l.number_or(c, "yDesired", 0.5)});
  if (j.contains("violated")) s.violated = l.string(j, "violated");
  return s;
}

}  // namespace

std::string write_handshake_trace(const HandshakeTrace& t) {
  std::string out = Json{{"format", "swarmcheck-trace"}, {"format_version", 1}, {"system", "handshake"},
                         {"obligation", t.obligation}, {"robots", t.robots}, {"master", t.master},
                         {"controller", t.controller}, {"tolerance", t.tolerance_m},
                         {"orient_tolerance", t.orient_tolerance_rad}, {"reorient", t.reorient_rad}}.dump() + "\n";
  for (const TraceStep& s : t.steps) {
    Json cs = Json::array();
    for (const TraceController& c : s.controllers)
      cs.push_back({{"onDestinationOutput", c.on_destination_output}, {"arrival", c.arrival},
                    {"accepted", c.accepted}, {"reached", c.reached}, {"x", c.x_m}, {"y", c.y_m},
                    {"theta", c.theta_rad}, {"xDesired", c.x_desired_m}, {"yDesired", c.y_desired_m}});
    Json j = {{"step", s.step}, {"flag", s.flag}, {"onDestinationOutput", s.on_destination_output},
              {"plan", s.plan}, {"controllers", cs}};
    if (!s.violated.empty()) j["violated"] = s.violated;
    out += j.dump() + "\n";
  }
  return out;
}

HandshakeTrace read_handshake_trace(const std::string& path) {
  io_input::check_input_file(path, "handshake trace", false);
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot read this file");
  HandshakeTrace t;
  std::string text;
  int number = 0;
  bool header = false;
  while (std::getline(in, text)) {
    ++number;
    if (text.find_first_not_of(" \t\r") == std::string::npos) continue;
    const Line l(path, number, text);
    if (!header) {
      read_header(l, t);
      header = true;
    } else {
      t.steps.push_back(read_step(l, t, static_cast<int64_t>(t.steps.size())));
    }
  }
  if (!header) throw InputError(fmt::format("{}:{}", path, number + 1), "expected the trace header line");
  if (t.steps.empty()) throw InputError(fmt::format("{}:{}", path, number + 1), "no step records after the header: nothing to show");
  return t;
}

int show_handshake_trace(const std::string& path, std::FILE* out) {
  const HandshakeTrace t = read_handshake_trace(path);
  fmt::print(out, "handshake trace of {}: {} robot(s), {} master, {} controller\n", t.obligation, t.robots,
             t.master, t.controller);
  fmt::print(out, "flag, out, ctrl out: the Environment's and each controller's onDestinationOutput at the\n"
                  "start of the step; plan: the Environment plans in the step; arr: the robot is at its\n"
                  "waypoint in the step (|dx| + |dy| < tolerance {:g} m); acc: accepts a waypoint in the step;\n"
                  "at: has reached its issued waypoint; dist: |dx| + |dy| in the step (m)\n\n", t.tolerance_m);
  std::string head = fmt::format("{:>5}  {:>4} {:>3} {:>4}", "step", "flag", "out", "plan");
  for (int32_t i = 0; i < t.robots; ++i) head += fmt::format("  | ctrl {:<2} out arr acc at     dist", i);
  fmt::print(out, "{}\n", head);
  for (const TraceStep& s : t.steps) {
    std::string row = fmt::format("{:>5}  {:>4} {:>3} {:>4}", s.step, s.flag, s.on_destination_output, s.plan ? "yes" : "-");
    for (const TraceController& c : s.controllers)
      row += fmt::format("  |         {:>3} {:>3} {:>3} {:>2} {:>8.3g}", c.on_destination_output, c.arrival ? 1 : 0,
                         c.accepted ? 1 : 0, c.reached ? 1 : 0,
                         std::fabs(c.x_desired_m - c.x_m) + std::fabs(c.y_desired_m - c.y_m));
    if (!s.violated.empty()) row += "   <- violates " + s.violated;
    fmt::print(out, "{}\n", row);
  }
  return 0;
}

}  // namespace swarmcheck::proofs::handshake
