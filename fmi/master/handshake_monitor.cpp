#include "fmi/master/handshake_monitor.hpp"

namespace swarmcheck::fmi::master {

HandshakeMonitor::HandshakeMonitor(const Master& m) {
  std::vector<std::string> environments;
  for (const std::string& in : m.instance_names()) {
    const std::string& model = m.model_name_of(in);
    if (model == "swarmcheck Environment") environments.push_back(in);
    if (model == "swarmcheck Controller") accepted_.emplace_back(in, m.port(in + ".accepted"));
  }
  if (environments.size() != 1 || accepted_.empty()) return;
  plans_ = m.port(environments[0] + ".planningSteps");
  last_.assign(accepted_.size(), 0);
  active_ = true;
}

void HandshakeMonitor::after_step(const Master& m) {
  if (!active_) return;
  const auto plans = static_cast<int64_t>(m.value(plans_));
  for (std::size_t k = 0; k < accepted_.size(); ++k) {
    const auto accepted = static_cast<int64_t>(m.value(accepted_[k].second));
    if (accepted > last_[k] && accepted > plans) {
      ++stale_count_;
      if (stale_.size() < 100) stale_.push_back({accepted_[k].first, m.steps(), m.time_s(), accepted, plans});
    }
    last_[k] = accepted;
  }
}

}  // namespace swarmcheck::fmi::master
