#include "views/view.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "spec/util/input_error.hpp"
#include "spec/util/input_file.hpp"
#include "spec/util/json_text.hpp"
#include "spec/util/utf8.hpp"

namespace swarmcheck::views {

std::string read_text_file(const std::string& path, const std::string& what) {
  return io_input::read_input_file(path, what);
}

std::vector<JsonLine> json_lines(const std::string& text, const std::string& path) {
  std::vector<JsonLine> out;
  int64_t number = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(pos, end - pos);
    pos = end + 1;
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    out.push_back({number, json_io::parse_json_text(line, path, number)});
  }
  return out;
}

ViewKind detect_view_kind(const std::string& text, const std::string& path) {
  const std::size_t bom = utf8::byte_order_mark_size(text);
  const std::size_t first = text.find_first_not_of(" \t\r\n", bom);
  if (first == std::string::npos) throw InputError(path, "empty file: expected a trace or an .fsm automaton");
  if (text[first] != '{') return ViewKind::fsm;
  const std::size_t end = text.find('\n', first);
  const json_io::Json h = json_io::parse_json_text(
      text.substr(first, end == std::string::npos ? std::string::npos : end - first), path,
      1 + static_cast<int64_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(first), '\n')));
  const std::string expected =
      "expected a trace header: {\"format\": \"swarmcheck-trace\", \"system\": \"exploration\" | "
      "\"handshake\", ...} or {\"format\": \"swarmcheck-mission-trace\", ...}";
  if (!h.is_object()) throw InputError(path + ":1", expected);
  const std::string format = json_io::string_member(h, "format");
  if (format == "swarmcheck-mission-trace") return ViewKind::mission;
  if (format != "swarmcheck-trace") throw InputError(path + ":1", expected);
  const std::string system = json_io::string_member(h, "system");
  if (system == "handshake") return ViewKind::handshake;
  if (system == "exploration") return h.contains("divergence") ? ViewKind::counterexample : ViewKind::exploration;
  throw InputError(path + ":1", expected);
}

Page view_page(const std::string& path, const ViewOptions& o) {
  const std::string text = read_text_file(path, "file to view");
  switch (detect_view_kind(text, path)) {
    case ViewKind::exploration:
    case ViewKind::counterexample: return exploration_page(text, path, o);
    case ViewKind::handshake: return handshake_page(text, path);
    case ViewKind::mission: return mission_page(text, path, o);
    case ViewKind::fsm: return fsm_page(text, path);
  }
  return {};
}

}  // namespace swarmcheck::views
