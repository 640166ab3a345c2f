#include "impl/dse/design_space.hpp"

#include <cmath>
#include <fmt/core.h>
#include <unordered_set>

#include "impl/dse/format.hpp"
#include "spec/exploration/rng.hpp"
#include "spec/exploration/scenario.hpp"
#include "spec/exploration/trace.hpp"

namespace swarmcheck::dse {
namespace {

__extension__ using U128 = unsigned __int128;   // for exact 64x64 -> 128-bit products

using exploration::CellIndex;
using exploration::Scenario;
using exploration::splitmix64;

constexpr uint64_t kReplicatePurpose = 0x7265706c69636174ULL;   // "replicat"
constexpr uint64_t kObstaclePurpose = 0x6f62737461636c65ULL;    // "obstacle"
constexpr uint64_t kRobotPurpose = 0x726f626f74730000ULL;       // "robots"

// The c-th draw of a counter-based stream, uniform in [0, n).
int64_t draw(uint64_t stream, uint64_t c, int64_t n) {
  const uint64_t h = splitmix64(stream ^ splitmix64(c));
  return static_cast<int64_t>((static_cast<U128>(h) * static_cast<uint64_t>(n)) >> 64);
}

// k distinct cells (raster indices i * N + j) among those `allowed`, in draw order. Sparse picks
// reject repeats; dense ones shuffle the allowed list (Fisher-Yates), both from `stream` alone.
template <class Allowed>
std::vector<int64_t> sample_cells(uint64_t stream, int64_t cells, int64_t allowed_count, int64_t k, Allowed allowed) {
  std::vector<int64_t> out;
  out.reserve(static_cast<std::size_t>(k));
  uint64_t c = 0;
  if (k * 2 <= allowed_count) {
    std::unordered_set<int64_t> taken;
    while (static_cast<int64_t>(out.size()) < k) {
      const int64_t x = draw(stream, c++, cells);
      if (allowed(x) && taken.insert(x).second) out.push_back(x);
    }
    return out;
  }
  std::vector<int64_t> pool;
  pool.reserve(static_cast<std::size_t>(allowed_count));
  for (int64_t x = 0; x < cells; ++x)
    if (allowed(x)) pool.push_back(x);
  for (int64_t i = 0; i < k; ++i) {
    const int64_t j = i + draw(stream, c++, static_cast<int64_t>(pool.size()) - i);
    std::swap(pool[static_cast<std::size_t>(i)], pool[static_cast<std::size_t>(j)]);
    out.push_back(pool[static_cast<std::size_t>(i)]);
  }
  return out;
}

void apply_scalar(Scenario& s, Knob k, const ParameterValue& v) {
  auto& p = s.params;
  switch (k) {
    case Knob::s_range: p.s_range = static_cast<int32_t>(v.number); break;
    case Knob::a1: p.a1 = v.number; break;
    case Knob::a2: p.a2 = v.number; break;
    case Knob::epsilon: p.epsilon = v.number; break;
    case Knob::max_ph: p.max_ph = v.number; break;
    case Knob::ertu: p.ertu = v.number; break;
    case Knob::eta: p.eta = v.number; break;
    case Knob::phi: p.phi = v.number; break;
    case Knob::lambda: p.lambda = v.number; break;
    case Knob::step_size: p.step_size = v.number; break;
    case Knob::map_size: s.map_size = static_cast<int32_t>(v.number); break;
    case Knob::cell_size: s.cell_size = v.number; break;
    case Knob::rule: s.rule = json_io::enum_from_string<exploration::RuleSet>(v.text, "rule"); break;
    case Knob::mode: s.mode = json_io::enum_from_string<exploration::Mode>(v.text, "mode"); break;
    case Knob::controller:
      s.controller = json_io::enum_from_string<exploration::ControllerKind>(v.text, "controller");
      break;
    case Knob::body: s.body.kind = json_io::enum_from_string<exploration::BodyKind>(v.text, "body"); break;
    case Knob::seed: s.seed = static_cast<uint64_t>(v.number); break;
    case Knob::max_steps: s.max_steps = static_cast<int64_t>(v.number); break;
    default: break;   // placement and replicates are applied by scenario()
  }
}

}  // namespace

uint64_t replicate_seed(uint64_t seed, int32_t replicate) {
  return splitmix64(splitmix64(seed ^ kReplicatePurpose) ^ static_cast<uint64_t>(replicate));
}

DesignSpace::DesignSpace(const DseConfig& config, Scenario base) : config_(config), base_(std::move(base)) {}

Genome DesignSpace::genome_of(uint64_t index) const {
  Genome g(config_.parameters.size());
  for (std::size_t k = config_.parameters.size(); k-- > 0;) {
    const uint64_t n = config_.parameters[k].values.size();
    g[k] = static_cast<int32_t>(index % n);
    index /= n;
  }
  return g;
}

uint64_t DesignSpace::index_of(const Genome& g) const {
  uint64_t index = 0;
  for (std::size_t k = 0; k < g.size(); ++k) index = index * config_.parameters[k].values.size() + static_cast<uint64_t>(g[k]);
  return index;
}

const ParameterValue* DesignSpace::value(const Genome& g, Knob k) const {
  for (std::size_t p = 0; p < config_.parameters.size(); ++p)
    if (config_.parameters[p].knob == k) return &config_.parameters[p].values[static_cast<std::size_t>(g[p])];
  return nullptr;
}

int32_t DesignSpace::replicates(const Genome& g) const {
  const ParameterValue* v = value(g, Knob::replicates);
  return v ? static_cast<int32_t>(v->number) : 1;
}

Scenario DesignSpace::scenario(const Genome& g, int32_t replicate) const {
  Scenario s = base_;
  for (std::size_t p = 0; p < config_.parameters.size(); ++p)
    apply_scalar(s, config_.parameters[p].knob, config_.parameters[p].values[static_cast<std::size_t>(g[p])]);
  if (replicate > 0) s.seed = replicate_seed(s.seed, replicate);
  const int64_t cells = int64_t{s.map_size} * s.map_size;
  const ParameterValue* robots = value(g, Knob::robot_count);
  const ParameterValue* count = value(g, Knob::obstacle_count);
  const ParameterValue* density = value(g, Knob::obstacle_density);
  const auto fail = [&](const std::string& what) -> InputError {
    return InputError("point " + describe(g) + (replicate > 0 ? ", replicate " + std::to_string(replicate) : ""), what);
  };
  if (count || density) {
    const int64_t n = count ? static_cast<int64_t>(count->number) : std::llround(density->number * static_cast<double>(cells));
    const int64_t robot_cells = robots ? static_cast<int64_t>(robots->number) : static_cast<int64_t>(s.robots.size());
    if (n + robot_cells > cells)
      throw fail(fmt::format("{} obstacles and {} robots do not fit in {} cells", n, robot_cells, cells));
    std::unordered_set<int64_t> kept;   // base robots' cells, when the robots are kept
    if (!robots)
      for (const auto& r : s.robots) {
        const int64_t i = static_cast<int64_t>(std::floor(r[0] / s.cell_size)), j = static_cast<int64_t>(std::floor(r[1] / s.cell_size));
        if (i >= 0 && j >= 0 && i < s.map_size && j < s.map_size) kept.insert(i * s.map_size + j);
      }
    const auto cells_list = sample_cells(splitmix64(s.seed ^ kObstaclePurpose), cells, cells - static_cast<int64_t>(kept.size()), n,
                                         [&](int64_t x) { return kept.count(x) == 0; });
    s.obstacles.clear();
    for (const int64_t x : cells_list)
      s.obstacles.push_back(CellIndex{static_cast<int32_t>(x / s.map_size), static_cast<int32_t>(x % s.map_size)});
  }
  if (robots) {
    const int64_t n = static_cast<int64_t>(robots->number);
    std::unordered_set<int64_t> blocked;
    for (const CellIndex& o : s.obstacles)
      if (o[0] >= 0 && o[1] >= 0 && o[0] < s.map_size && o[1] < s.map_size) blocked.insert(int64_t{o[0]} * s.map_size + o[1]);
    const int64_t free_cells = cells - static_cast<int64_t>(blocked.size());
    if (n > free_cells) throw fail(fmt::format("{} robots do not fit in {} free cells", n, free_cells));
    const auto cells_list = sample_cells(splitmix64(s.seed ^ kRobotPurpose), cells, free_cells, n,
                                         [&](int64_t x) { return blocked.count(x) == 0; });
    s.robots.clear();
    for (const int64_t x : cells_list)
      s.robots.push_back({(static_cast<double>(x / s.map_size) + 0.5) * s.cell_size, (static_cast<double>(x % s.map_size) + 0.5) * s.cell_size});
  }
  try {
    exploration::validate(s);
  } catch (const InputError& e) {
    throw fail(e.what());
  }
  return s;
}

Value DesignSpace::knob_value(const Genome& g, Knob k) const {
  if (const ParameterValue* v = value(g, k))
    return knob_info(k).type == ValueType::text ? Value::of_text(v->text) : Value::of_number(v->number);
  const Scenario& s = base_;
  const auto& p = s.params;
  switch (k) {
    case Knob::s_range: return Value::of_number(p.s_range);
    case Knob::a1: return Value::of_number(p.a1);
    case Knob::a2: return Value::of_number(p.a2);
    case Knob::epsilon: return Value::of_number(p.epsilon);
    case Knob::max_ph: return Value::of_number(p.max_ph);
    case Knob::ertu: return Value::of_number(p.ertu);
    case Knob::eta: return Value::of_number(p.eta);
    case Knob::phi: return Value::of_number(p.phi);
    case Knob::lambda: return Value::of_number(p.lambda);
    case Knob::step_size: return Value::of_number(p.step_size);
    case Knob::map_size: return Value::of_number(s.map_size);
    case Knob::cell_size: return Value::of_number(s.cell_size);
    case Knob::robot_count: return Value::of_number(static_cast<double>(s.robots.size()));
    case Knob::obstacle_count: return Value::of_number(static_cast<double>(s.obstacles.size()));
    case Knob::obstacle_density: return Value::of_number(static_cast<double>(s.obstacles.size()) / (double(s.map_size) * s.map_size));
    case Knob::rule: return Value::of_text(json_io::enum_to_string(s.rule));
    case Knob::mode: return Value::of_text(json_io::enum_to_string(s.mode));
    case Knob::controller: return Value::of_text(json_io::enum_to_string(s.controller));
    case Knob::body: return Value::of_text(json_io::enum_to_string(s.body.kind));
    case Knob::seed: return Value::of_number(static_cast<double>(s.seed));
    case Knob::max_steps: return Value::of_number(static_cast<double>(s.max_steps));
    case Knob::replicates: return Value::of_number(1);
  }
  return Value::of_number(0);
}

int32_t DesignSpace::violated_parameter_constraint(const Genome& g) const {
  const NameValues values = [&](const std::string& name) { return knob_value(g, *knob_of(name)); };
  for (std::size_t c = 0; c < config_.parameter_constraints.size(); ++c)
    if (!config_.parameter_constraints[c].expression.evaluate(values)) return static_cast<int32_t>(c);
  return -1;
}

std::string DesignSpace::point_key(const Genome& g) const {
  exploration::Fnv1a h;
  const auto add_text = [&h](const std::string& t) {
    for (const char c : t) {
      h.h ^= static_cast<unsigned char>(c);
      h.h *= 0x100000001b3ULL;
    }
  };
  add_text(std::string("swarmcheck-dse-point ") + exploration::kToolVersion + "\n");
  const int32_t n = replicates(g);
  for (int32_t r = 0; r < n; ++r) add_text(json_io::to_json(scenario(g, r)).dump() + "\n");
  return fmt::format("{:016x}", h.h);
}

std::string DesignSpace::describe(const Genome& g, bool varying_only) const {
  bool any_varying = false;
  for (const SweptParameter& p : config_.parameters) any_varying = any_varying || p.values.size() > 1;
  std::string out;
  for (std::size_t p = 0; p < config_.parameters.size(); ++p) {
    if (varying_only && any_varying && config_.parameters[p].values.size() == 1) continue;
    const ParameterValue& v = config_.parameters[p].values[static_cast<std::size_t>(g[p])];
    out += (out.empty() ? "" : ", ") + plain_name(config_.parameters[p].name) + "=" + value_text(v);
  }
  return out;
}

}  // namespace swarmcheck::dse
