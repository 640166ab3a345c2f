#pragma once
// The FMUs' library runs without oneTBB (it must load on machines that do not have libtbb):
// this folder stands in for the oneTBB headers that impl/exploration includes, running every
// parallel construct on the calling thread. impl's results never depend on its threads (the
// conformance contract), so an FMU computes the same bits as the library on any thread count.
// Only the subset impl/exploration uses is here; fmi/CMakeLists.txt puts this folder first on
// the FMU library's include path.
#include <utility>

namespace tbb {

class task_arena {
 public:
  explicit task_arena(int /*max_concurrency*/ = 1) {}
  int max_concurrency() const { return 1; }
  template <class F>
  decltype(auto) execute(F&& f) {
    return std::forward<F>(f)();
  }
};

namespace this_task_arena {
inline int current_thread_index() { return 0; }   // the calling thread is slot 0
inline int max_concurrency() { return 1; }
}  // namespace this_task_arena

}  // namespace tbb
