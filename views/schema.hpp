#pragma once
// The JSON Schema of scenario files, generated from the Hana declarations (spec/exploration/
// types.hpp: keys, types, enums, list shapes) and the domain table (spec/exploration/domains.hpp:
// bounds and the "expected ..." texts). web/validate.js validates with it and gives the CLI's
// messages; "x-" keywords carry what JSON Schema cannot say (messages, cross-key rules, order).
#include "spec/util/hana_json.hpp"

namespace swarmcheck::views {

json_io::Json scenario_schema();

}  // namespace swarmcheck::views
