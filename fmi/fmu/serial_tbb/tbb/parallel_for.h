#pragma once
// Serial stand-in for oneTBB (see task_arena.h): the body runs once over the whole range (a
// split TBB may choose; callers already handle any split), or once per index in order.
#include "blocked_range.h"
#include "partitioner.h"

namespace tbb {

template <class Range, class Body, class Partitioner>
void parallel_for(const Range& range, const Body& body, Partitioner& /*partitioner*/) {
  if (!range.empty()) body(range);
}
template <class Range, class Body>
void parallel_for(const Range& range, const Body& body) {
  if (!range.empty()) body(range);
}
template <class Index, class Function>
void parallel_for(Index first, Index last, const Function& f) {
  for (Index k = first; k < last; ++k) f(k);
}

}  // namespace tbb
