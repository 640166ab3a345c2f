#include "impl/dse/sweep.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "impl/dse/genetic.hpp"
#include "impl/dse/journal.hpp"
#include "spec/util/budget.hpp"
#include "swarmcheck/exploration.hpp"

namespace swarmcheck::dse {
namespace {

bool stopped(const std::atomic<bool>* stop) { return stop && stop->load(std::memory_order_relaxed); }

// One batch through the journal and the executor, outcomes in batch order.
class BatchRunner {
 public:
  BatchRunner(const DesignSpace& space, Executor& executor, const SweepOptions& options)
      : space_(space), executor_(executor), options_(options), columns_(needed_columns(space.config())),
        journal_(options.journal_path) {}

  // nullopt when interrupted before every point was finished.
  std::optional<std::vector<PointOutcome>> run(const std::vector<Genome>& batch, int32_t generation) {
    std::vector<PointOutcome> out(batch.size());
    std::vector<Genome> pending;
    std::vector<std::size_t> pending_at;
    std::vector<std::string> labels;
    SweepProgress progress{0, batch.size(), result_.computed, generation};
    for (std::size_t i = 0; i < batch.size(); ++i) {
      out[i].genome = batch[i];
      out[i].generation = generation;
      out[i].violated_parameter_constraint = space_.violated_parameter_constraint(batch[i]);
      if (out[i].violated_parameter_constraint >= 0) {
        ++progress.done;
        continue;
      }
      const PointRuns* known = journal_.find(space_.point_key(batch[i]));
      if (known && has_columns(*known, columns_)) {
        out[i].runs = *known;
        ++result_.from_journal;
        ++progress.done;
        continue;
      }
      pending.push_back(batch[i]);
      pending_at.push_back(i);
      labels.push_back(space_.describe(batch[i]));
    }
    if (options_.on_progress) options_.on_progress(progress);
    std::size_t finished = 0;
    executor_.evaluate(pending, [&](std::size_t k, PointRuns runs) {
      journal_.append(runs, labels[k]);
      result_.runs += runs.runs.size();
      out[pending_at[k]].runs = std::move(runs);
      ++finished;
      ++result_.computed;
      ++progress.done;
      progress.computed = result_.computed;
      if (options_.on_progress) options_.on_progress(progress);
    });
    journal_.sync();
    if (finished < pending.size()) return std::nullopt;
    return out;
  }

  SweepOutcome& result() { return result_; }

 private:
  const DesignSpace& space_;
  Executor& executor_;
  const SweepOptions& options_;
  std::vector<Column> columns_;
  Journal journal_;
  SweepOutcome result_;
};

}  // namespace

ThreadExecutor::ThreadExecutor(const DesignSpace& space, std::vector<Column> columns, int32_t threads,
                               const std::atomic<bool>* stop)
    : space_(space), columns_(std::move(columns)), threads_(threads), stop_(stop) {}

void ThreadExecutor::evaluate(const std::vector<Genome>& batch, const std::function<void(std::size_t, PointRuns)>& done) {
  std::mutex report;
  tbb::task_arena arena(threads_ > 0 ? threads_ : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 1), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        if (stopped(stop_)) return;
        PointRuns runs = evaluate_point(space_, batch[i], columns_);
        const std::lock_guard lock(report);
        done(i, std::move(runs));
      }
    }, tbb::simple_partitioner());
  });
}

namespace {
// What a point's runs need in memory: they go one after another on one thread, so the largest's.
struct PointNeed {
  double bytes = -1;
  Genome genome;
  int32_t map_size = 0;
  std::size_t robots = 0;
};

// point_problem, noting in `need` (when given) the largest run's estimated memory, from the same
// scenarios (a point's scenarios are built once for both).
std::optional<std::string> check_point(const DesignSpace& space, const Genome& g, PointNeed* need) {
  try {
    const int32_t n = space.replicates(g);
    for (int32_t r = 0; r < n; ++r) {
      const exploration::Scenario s = space.scenario(g, r);
      for (const Objective& o : space.config().objectives) {
        const std::string where = "objectiveDefinitions.internalFunctions[\"" + o.name + "\"]";
        if (o.column.series == Series::turning && s.mode == exploration::Mode::abstract)
          return where + ": turning is a cosim output (abstract robots do not turn); point " + space.describe(g) + " runs in abstract mode";
        if (o.column.robot >= static_cast<int32_t>(s.robots.size()))
          return where + ": column " + o.column.name + " names robot " + std::to_string(o.column.robot + 1) + " but point " +
                 space.describe(g) + " has " + std::to_string(s.robots.size()) + " robots";
      }
      if (need) {
        const double bytes = static_cast<double>(exploration::Exploration::estimated_bytes(s));
        if (bytes > need->bytes) *need = PointNeed{bytes, g, s.map_size, s.robots.size()};
      }
    }
  } catch (const InputError& e) {
    return std::string(e.what());
  }
  return std::nullopt;
}

// The `points_at_once` largest points together must fit (named after the largest).
double require_points_fit(const DesignSpace& space, std::vector<PointNeed> needs, std::uint64_t memory_limit_bytes,
                          int32_t points_at_once) {
  if (needs.empty()) return 0;
  const std::size_t k = std::min(needs.size(), static_cast<std::size_t>(std::max(1, points_at_once)));
  std::partial_sort(needs.begin(), needs.begin() + static_cast<std::ptrdiff_t>(k), needs.end(),
                    [](const PointNeed& a, const PointNeed& b) { return a.bytes > b.bytes; });
  double together = 0;
  for (std::size_t i = 0; i < k; ++i) together += needs[i].bytes;
  const PointNeed& largest = needs.front();
  const std::string at_once =
      k > 1 ? fmt::format(", with the {} largest points at once (--threads {}; --threads 1 runs one at a time)", k, k) : "";
  require_within(space.config().file,
                 fmt::format("design point {}: a {} x {} map with {} robots{}", space.describe(largest.genome),
                             largest.map_size, largest.map_size, largest.robots, at_once),
                 together, memory_limit_bytes, "--memory-limit");
  return together;
}
}  // namespace

std::optional<std::string> point_problem(const DesignSpace& space, const Genome& g) { return check_point(space, g, nullptr); }

double check_design_space(const DesignSpace& space, std::uint64_t memory_limit_bytes, int32_t points_at_once) {
  const DseConfig& c = space.config();
  std::vector<PointNeed> needs;
  const auto check = [&](const Genome& g) {
    if (space.violated_parameter_constraint(g) >= 0) return;
    PointNeed need;
    if (auto problem = check_point(space, g, &need)) throw InputError(c.file, *problem);
    if (need.bytes >= 0) needs.push_back(std::move(need));
  };
  if (c.algorithm == Algorithm::exhaustive) {
    for (uint64_t i = 0; i < space.size(); ++i) check(space.genome_of(i));
  } else {
    // Genetic: each value once, the other parameters at their first value.
    for (std::size_t p = 0; p < c.parameters.size(); ++p)
      for (std::size_t v = 0; v < c.parameters[p].values.size(); ++v) {
        Genome g(c.parameters.size(), 0);
        g[p] = static_cast<int32_t>(v);
        check(g);
      }
  }
  return require_points_fit(space, std::move(needs), memory_limit_bytes, points_at_once);
}

SweepOutcome run_sweep(const DesignSpace& space, Executor& executor, const SweepOptions& options) {
  BatchRunner runner(space, executor, options);
  if (space.config().algorithm == Algorithm::exhaustive) {
    std::vector<Genome> all;
    for (uint64_t i = 0; i < space.size(); ++i) all.push_back(space.genome_of(i));
    auto outcomes = runner.run(all, 0);
    SweepOutcome r = std::move(runner.result());
    r.interrupted = !outcomes.has_value();
    if (outcomes) r.points = std::move(*outcomes);
    r.generations = 0;
    return r;
  }
  const GeneticOutcome g = run_genetic(space, [&](const std::vector<Genome>& batch, int32_t generation) {
    return runner.run(batch, generation);
  });
  SweepOutcome r = std::move(runner.result());
  r.points = g.points;
  r.generations = g.generations;
  r.interrupted = g.interrupted;
  return r;
}

}  // namespace swarmcheck::dse
