#pragma once
// SWARM_DEMAND: an always-on assertion for spec/ and model/ (a broken invariant is a programmer
// error, never bad input: bad input is an InputError). Like Drake's DRAKE_DEMAND.
#include <cstdio>
#include <cstdlib>

#define SWARM_DEMAND(cond)                                                                   \
  do {                                                                                       \
    if (!(cond)) {                                                                           \
      std::fprintf(stderr, "%s:%d: invariant failed: %s\n", __FILE__, __LINE__, #cond);     \
      std::abort();                                                                          \
    }                                                                                        \
  } while (0)

// SWARM_ASSERT: debug-only, for impl/ hot loops.
#ifdef NDEBUG
#define SWARM_ASSERT(cond) ((void)0)
#else
#define SWARM_ASSERT(cond) SWARM_DEMAND(cond)
#endif
