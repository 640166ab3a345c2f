#include "fmi/fmu/environment_run.hpp"

#include <cmath>
#include <cstdio>

#include "fmi/fmu/kinds.hpp"
#include "impl/exploration/environment.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/util/input_error.hpp"

namespace swarmcheck::fmi {
namespace {

namespace ex = swarmcheck::exploration;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

EnvironmentRun::EnvironmentRun() = default;
EnvironmentRun::~EnvironmentRun() = default;

void EnvironmentRun::start(const ex::Scenario& s) {
  clear();
  env_ = std::make_unique<impl::exploration::Environment>(s, ExplorationOptions{});
}

void EnvironmentRun::clear() {
  env_.reset();
  history_.clear();
}

const ex::EnvironmentState& EnvironmentRun::state() const { return env_->state(); }

void EnvironmentRun::step(bool verdict, bool planned) {
  if (env_->state().tick >= ex::kStepsMax) throw FmuError("doStep: the Environment has taken its last step (2^31 - 1)");
  if (planned) env_->step_planned(verdict);
  else env_->step(verdict);
  history_.push_back(verdict ? 1 : 0);
}

void EnvironmentRun::save(std::vector<uint8_t>& out) const {
  out.push_back(env_ ? 1 : 0);
  put_state_u64(out, history_.size());
  out.insert(out.end(), history_.begin(), history_.end());
}

void EnvironmentRun::restore(std::span<const uint8_t>& in, const std::function<ex::Scenario()>& scenario, bool planned) {
  if (in.empty()) throw FmuError("FMU state: the bytes end early (not a state of this FMU)");
  const bool initialised = in[0] == 1;
  in = in.subspan(1);
  const uint64_t steps = take_state_u64(in);
  if (steps > in.size()) throw FmuError("FMU state: the bytes end early (not a state of this FMU)");
  std::vector<uint8_t> history(in.begin(), in.begin() + static_cast<std::ptrdiff_t>(steps));
  in = in.subspan(static_cast<std::size_t>(steps));
  if (!initialised && !history.empty()) throw FmuError("FMU state: steps recorded before initialisation");
  clear();
  if (!initialised) return;
  start(scenario());
  for (const uint8_t verdict : history) step(verdict == 1, planned);
}

int64_t environment_steps_in(double h_s, double step_s) {
  const double n = std::round(h_s / step_s);
  if (n >= 1 && n <= 1e12 && std::fabs(h_s - n * step_s) <= 1e-9 * n * step_s) return static_cast<int64_t>(n);
  throw FmuError("doStep: the communication step " + number(h_s) + " s is not a whole multiple of step_size " +
                 number(step_s) + " s (within a relative 1e-9)");
}

void validate_parameters(const ex::Scenario& s, const std::string& keys) {
  try {
    ex::validate(s);
  } catch (const InputError& e) {
    throw FmuError(std::string("the parameters do not make a valid scenario: ") + e.what() + " (" + keys + ")");
  }
}

}  // namespace swarmcheck::fmi
