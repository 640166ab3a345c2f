#pragma once
// Driving a sweep: the points to run (all of the full factorial, or the genetic search's
// generations), the journal (points already there are not run again), and an Executor that
// evaluates a batch of points however it likes: oneTBB threads here, Open MPI ranks in the app.
// The outcome lists the points in a fixed order whatever the executor's completion order.
//
//   DesignSpace space(config, base);
//   check_design_space(space);                // bad input: InputError, before anything is written
//   ThreadExecutor threads(space, needed_columns(config), 2, &stop_flag);
//   SweepOutcome out = run_sweep(space, threads, {"out/journal.jsonl", &stop_flag, nullptr});
#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "impl/dse/design_space.hpp"
#include "impl/dse/evaluate.hpp"
#include "impl/dse/results.hpp"

namespace swarmcheck::dse {

class Executor {
 public:
  virtual ~Executor() = default;
  // Evaluates every genome of the batch and calls done(i, runs) once per finished one, never
  // from two threads at once. When stop becomes true, points not started are left out and
  // the points in flight finish (and are reported) before it returns.
  virtual void evaluate(const std::vector<Genome>& batch,
                        const std::function<void(std::size_t, PointRuns)>& done) = 0;
};

// Points in parallel on oneTBB threads (each run on one thread).
class ThreadExecutor : public Executor {
 public:
  ThreadExecutor(const DesignSpace& space, std::vector<Column> columns, int32_t threads,
                 const std::atomic<bool>* stop);
  void evaluate(const std::vector<Genome>& batch, const std::function<void(std::size_t, PointRuns)>& done) override;

 private:
  const DesignSpace& space_;
  std::vector<Column> columns_;
  int32_t threads_;
  const std::atomic<bool>* stop_;
};

struct SweepProgress {
  std::size_t done = 0;        // points finished in this batch (journal hits included)
  std::size_t total = 0;       // points of this batch
  std::size_t computed = 0;    // points run in this invocation so far
  int32_t generation = 0;
};

struct SweepOptions {
  std::string journal_path;
  const std::atomic<bool>* stop = nullptr;
  std::function<void(const SweepProgress&)> on_progress;
};

struct SweepOutcome {
  std::vector<PointOutcome> points;
  bool interrupted = false;
  std::size_t computed = 0;       // points run now
  std::size_t from_journal = 0;   // points found in the journal
  std::size_t runs = 0;           // simulations behind the computed points
  int32_t generations = 0;
};

// Every problem a point could have, found before anything runs: for the full factorial every
// point's every replicate; for a genetic search each value on the base (other combinations
// are checked as the search draws them). Throws InputError naming the point. With a memory limit
// (bytes; 0: none), a point whose runs, `points_at_once` of them in memory together, are
// estimated to need more is refused (BudgetExceeded, naming the point and the limit's flag).
// Returns that estimate (bytes: the largest points that run at once, added up).
double check_design_space(const DesignSpace& space, std::uint64_t memory_limit_bytes = 0, int32_t points_at_once = 1);
// The problem of one point (its scenarios, objective columns it cannot offer), or nullopt.
std::optional<std::string> point_problem(const DesignSpace& space, const Genome& g);

SweepOutcome run_sweep(const DesignSpace& space, Executor& executor, const SweepOptions& options);

}  // namespace swarmcheck::dse
