#pragma once
// One self-contained HTML page: web/page.html with every stylesheet and every ES module of web/
// inlined (imports dropped, exports unwrapped: the modules share one module scope), and the
// page's data as JSON in <script type="application/json" id="swarmcheck-data">. The page's
// Content-Security-Policy allows no network at all (connect-src 'self' only, for `serve`).
#include <string>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::views {

struct Page {
  std::string title;
  json_io::Json data;   // data["kind"] chooses what web/main.js shows
};

std::string assemble_page(const Page& p);

// The JSON text made safe inside a <script> element (every '<' written as \u003c).
std::string script_safe_json(const json_io::Json& j);

// The modules of web/ in dependency order, as one script (what assemble_page inlines).
std::string bundled_modules();

}  // namespace swarmcheck::views
