#pragma once
// Serial stand-in for oneTBB (see task_arena.h): a task runs when it is handed over.
#include <utility>

namespace tbb {

class task_group {
 public:
  template <class F>
  void run(F&& f) {
    std::forward<F>(f)();
  }
  void wait() {}
};

}  // namespace tbb
