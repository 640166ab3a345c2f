#pragma once
// Watches the onDestination handshake of a swarmcheck multi-model while the master runs it: the
// property `swarmcheck prove` states as fresh-acceptance (proofs/obligations/handshake_*): a
// controller only accepts a waypoint issued since its last acceptance. Each swarmcheck
// Controller counts its acceptances (output `accepted`), the Environment its plans (output
// `planningSteps`); both start at 0 and a fresh acceptance follows a plan, so a controller whose
// count passes the plans' has accepted a stale waypoint. Inactive when the multi-model has no
// swarmcheck Environment (or more than one).
#include <cstdint>
#include <string>
#include <vector>

#include "fmi/master/master.hpp"

namespace swarmcheck::fmi::master {

class HandshakeMonitor {
 public:
  explicit HandshakeMonitor(const Master& m);
  bool active() const { return active_; }
  void after_step(const Master& m);

  struct StaleAcceptance {
    std::string controller;   // "{Controller}.controller2"
    int64_t step = 0;         // master steps done when it was seen
    double time_s = 0;
    int64_t accepted = 0, plans = 0;
  };
  const std::vector<StaleAcceptance>& stale() const { return stale_; }   // the first 100
  int64_t stale_count() const { return stale_count_; }

 private:
  bool active_ = false;
  Master::Port plans_;
  std::vector<std::pair<std::string, Master::Port>> accepted_;
  std::vector<int64_t> last_;
  std::vector<StaleAcceptance> stale_;
  int64_t stale_count_ = 0;
};

}  // namespace swarmcheck::fmi::master
