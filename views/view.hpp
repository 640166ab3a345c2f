#pragma once
// `swarmcheck view FILE`: what FILE is, and the page that shows it. Every reader checks its input
// like the other verbs do: bad input is an InputError naming file:line and what was expected.
#include <atomic>
#include <cstdint>
#include <string>

#include "spec/util/hana_json.hpp"
#include "views/page.hpp"

namespace swarmcheck::views {

enum class ViewKind { exploration, counterexample, handshake, mission, fsm };

struct ViewOptions {
  int64_t max_records = 4000;   // longer traces are thinned evenly (field records always kept)
  std::string mission_path;     // a mission trace's mission file (default: its header's name, next to the trace)
};

// From the file's first line: a JSON trace header (exploration, counterexample, handshake or
// mission trace), else an .fsm automaton.
ViewKind detect_view_kind(const std::string& text, const std::string& path);

// The page for FILE. Handshake traces are checked by the caller (proofs/ reads them; views/ may
// not include proofs/), then shown from their JSON lines.
Page view_page(const std::string& path, const ViewOptions& o);

Page exploration_page(const std::string& text, const std::string& path, const ViewOptions& o);
Page handshake_page(const std::string& text, const std::string& path);
Page mission_page(const std::string& text, const std::string& path, const ViewOptions& o);
// The mission file a mission trace is shown with: --mission, else the file of the name its header
// gives, in the trace's folder (never the header's path as written).
std::string mission_file_of_trace(const std::string& text, const std::string& path, const ViewOptions& o);
// cancel: dot is killed when it is set (a server stopping).
Page fsm_page(const std::string& text, const std::string& path, const std::atomic<bool>* cancel = nullptr);

// The colours of the heat map, obstacles and robots (views/svg.hpp), for the pages.
json_io::Json exploration_palette();

// Reads a whole file (InputError when it cannot be opened).
std::string read_text_file(const std::string& path, const std::string& what);

// Splits JSON Lines; returns each non-empty line with its 1-based number.
struct JsonLine {
  int64_t number;
  json_io::Json json;
};
std::vector<JsonLine> json_lines(const std::string& text, const std::string& path);

}  // namespace swarmcheck::views
