#pragma once
// The page sources of web/ (HTML, CSS, ES modules), embedded in the binary at build time by
// cmake/EmbedWeb.cmake: views are self-contained files and `serve` needs no folder at run time.
#include <span>
#include <string_view>

namespace swarmcheck::views {

struct WebAsset {
  std::string_view name;   // file name in web/, e.g. "map.js"
  std::string_view text;
};

std::span<const WebAsset> web_assets();

// The text of web/<name>; the name must exist (a missing asset is a build error in swarmcheck).
std::string_view web_asset(std::string_view name);

}  // namespace swarmcheck::views
