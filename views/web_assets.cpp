#include "views/web_assets.hpp"

#include <string>

#include "spec/util/demand.hpp"

namespace swarmcheck::views {

std::string_view web_asset(std::string_view name) {
  for (const WebAsset& a : web_assets())
    if (a.name == name) return a.text;
  std::fprintf(stderr, "swarmcheck: web asset %s is not embedded\n", std::string(name).c_str());
  SWARM_DEMAND(false);
  return {};
}

}  // namespace swarmcheck::views
