#pragma once
// The automata and mission campaigns of `swarmcheck conform` (the exploration campaign, which MPI
// can split across ranks, is in conform_verb.cpp): run one, print its report as text or JSON.
#include <chrono>
#include <cstdint>
#include <string>

#include "spec/util/hana_json.hpp"

namespace swarmcheck::cli {

struct SystemCampaign {
  int cases = 0;          // 0: the campaign's default budget
  uint64_t seed = 1;
  std::string out_dir;
  bool json = false;
  bool stats = false;
  bool progress = false;  // on a terminal: case counts on stderr
  std::chrono::milliseconds quiet_limit{std::chrono::seconds(60)};   // --case-time-limit
};

// Each returns 0 (agree) or 1 (a counterexample, written and described); with json, the report
// object is stored in *json_out instead of printed.
int conform_automata(const SystemCampaign& c, json_io::Json* json_out);
int conform_missions(const SystemCampaign& c, json_io::Json* json_out);

}  // namespace swarmcheck::cli
