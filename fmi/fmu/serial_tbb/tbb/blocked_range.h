#pragma once
// Serial stand-in for oneTBB (see task_arena.h).
#include <cstddef>

namespace tbb {

template <class Value>
class blocked_range {
 public:
  blocked_range(Value begin, Value end, std::size_t grainsize = 1) : begin_(begin), end_(end), grainsize_(grainsize) {}
  Value begin() const { return begin_; }
  Value end() const { return end_; }
  std::size_t grainsize() const { return grainsize_; }
  bool empty() const { return !(begin_ < end_); }

 private:
  Value begin_, end_;
  std::size_t grainsize_;
};

}  // namespace tbb
