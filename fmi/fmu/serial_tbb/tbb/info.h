#pragma once
// Serial stand-in for oneTBB (see task_arena.h): one thread.
namespace tbb::info {
inline int default_concurrency() { return 1; }
}  // namespace tbb::info
