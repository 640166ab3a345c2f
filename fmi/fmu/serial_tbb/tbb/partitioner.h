#pragma once
// Serial stand-in for oneTBB (see task_arena.h): partitioners choose nothing on one thread.
namespace tbb {
class affinity_partitioner {};
class auto_partitioner {};
class simple_partitioner {};
class static_partitioner {};
}  // namespace tbb
