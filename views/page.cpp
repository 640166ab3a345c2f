#include "views/page.hpp"

#include <array>
#include <string_view>

#include "spec/util/demand.hpp"
#include "views/svg.hpp"
#include "views/web_assets.hpp"

namespace swarmcheck::views {
namespace {

// Dependency order: a module comes after every module it imports.
constexpr std::array<std::string_view, 15> kModules{
    "util.js",     "field.js",         "map.js",         "timeline.js",
    "charts.js",   "validate.js",      "view_exploration.js", "view_counterexample.js",
    "view_handshake.js", "view_mission.js", "view_fsm.js", "editor.js",
    "mission_editor.js", "live.js",    "main.js"};

constexpr std::array<std::string_view, 1> kStyles{"common.css"};

// `import ... from '...';` lines go (everything is in one scope); `export ` before a
// declaration goes. Imports must be one line each (web/README.md).
std::string unwrap_module(std::string_view text) {
  std::string out;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    if (line.starts_with("import ")) continue;
    if (line.starts_with("export ")) line.remove_prefix(7);
    out.append(line);
    out += '\n';
  }
  return out;
}

void replace_once(std::string& s, std::string_view marker, const std::string& with) {
  const std::size_t at = s.find(marker);
  SWARM_DEMAND(at != std::string::npos);
  s.replace(at, marker.size(), with);
}

}  // namespace

std::string script_safe_json(const json_io::Json& j) {
  const std::string text = j.dump(-1, ' ', false, json_io::Json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    if (c == '<') out += "\\u003c";
    else out += c;
  }
  return out;
}

std::string bundled_modules() {
  std::string js;
  for (const std::string_view m : kModules) {
    js += "// ---- web/" + std::string(m) + " ----\n";
    js += unwrap_module(web_asset(m));
  }
  SWARM_DEMAND(js.find("</script") == std::string::npos);
  return js;
}

std::string assemble_page(const Page& p) {
  SWARM_DEMAND(p.data.is_object());
  SWARM_DEMAND(p.data.contains("kind"));
  std::string css;
  for (const std::string_view s : kStyles) css += std::string(web_asset(s));
  // Markers are replaced in the order they appear, each in what precedes the inserted text,
  // so the inserted data can never be mistaken for a marker.
  std::string html(web_asset("page.html"));
  const std::size_t data_at = html.find("{{DATA}}");
  SWARM_DEMAND(data_at != std::string::npos);
  std::string head = html.substr(0, data_at);
  std::string tail = html.substr(data_at + 8);
  replace_once(head, "{{CSS}}", css);   // ours first: the title is the user's text
  replace_once(head, "{{TITLE}}", xml_escape(p.title));
  replace_once(tail, "{{JS}}", bundled_modules());
  return head + script_safe_json(p.data) + tail;
}

}  // namespace swarmcheck::views
