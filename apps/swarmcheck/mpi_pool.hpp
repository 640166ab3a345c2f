#pragma once
// Distribution over Open MPI ranks, for the verbs that split work (`dse`, `conform`): rank 0
// owns every file and hands out tasks one at a time to whichever rank asks next (dynamic load
// balancing: tasks differ a lot in cost); the other ranks only compute. Tasks and replies are
// text. Open MPI is optional: without it (SWARMCHECK_HAVE_MPI unset) the binary still builds,
// and a run under mpirun says how to get MPI instead of running K copies of the same work.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace swarmcheck::cli::mpi {

// This process's place when started by mpirun (Open MPI's or PMI's environment), else 0 of 1.
struct Launch {
  int rank = 0;
  int size = 1;
};
Launch launch_from_environment();

bool compiled_in();
// The message for a multi-rank launch of a binary built without MPI.
std::string missing_mpi_message();

// MPI_Init on construction, MPI_Finalize on destruction (one per process).
class Session {
 public:
  Session();
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  // Ends every rank at once (after an error on rank 0, so that no worker waits forever).
  [[noreturn]] static void abort(int status);

 private:
  int rank_ = 0, size_ = 1;
};

// Rank 0: sends every task not skipped (skip(i) is asked just before task i would go out) to
// the next idle rank and calls done(i, reply) as replies come back, on this thread. Returns
// when every task sent has been answered. Can be called again (the workers wait in between).
void distribute(const std::vector<std::string>& tasks, const std::function<void(std::size_t, std::string)>& done,
                const std::function<bool(std::size_t)>& skip);
// Rank 0: lets the workers return from serve().
void release_workers();
// Ranks > 0: answers tasks with work(task) until released.
void serve(const std::function<std::string(const std::string&)>& work);

}  // namespace swarmcheck::cli::mpi
