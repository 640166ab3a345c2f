#pragma once
// The object `swarmcheck prove --json` prints, from the runner's reports. One definition for the
// command line and the Python package (swarmcheck.prove returns this dict).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "proofs/obligations/runner.hpp"

namespace swarmcheck::proofs {

// The label, time and answer of the query that took longest (where an obligation's time goes).
inline nlohmann::ordered_json slowest_query_json(const ObligationReport& r) {
  const QueryRecord* worst = nullptr;
  for (const QueryRecord& q : r.queries)
    if (!worst || q.seconds > worst->seconds) worst = &q;
  if (!worst) return nullptr;
  return nlohmann::ordered_json{{"label", worst->label}, {"seconds", worst->seconds}, {"answer", worst->answer}};
}

// `traces[k]`: where report k's counterexample trace was written, or empty.
inline nlohmann::ordered_json prove_report_json(const std::vector<ObligationReport>& reports, double total,
                                                const std::vector<std::string>& traces) {
  using Json = nlohmann::ordered_json;
  Json list = Json::array();
  for (std::size_t k = 0; k < reports.size(); ++k) {
    const ObligationReport& r = reports[k];
    Json j = {{"name", r.name},         {"property", r.property},
              {"expected", to_string(r.expected)},
              {"result", to_string(r.result)},
              {"met", r.met()},         {"seconds", r.seconds},
              {"queries", r.queries.size()},
              {"slowest_query", slowest_query_json(r)},
              {"detail", r.detail},     {"assumptions", r.assumptions},
              {"reads", r.reads},       {"step_calls", r.step_calls},
              {"unread", r.unread}};
    if (k < traces.size() && !traces[k].empty()) j["trace"] = traces[k];
    list.push_back(j);
  }
  bool all_met = true;
  for (const ObligationReport& r : reports) all_met = all_met && r.met();
  return Json{{"obligations", list}, {"all_met", all_met}, {"total_seconds", total}};
}

}  // namespace swarmcheck::proofs
