// Invariants of the engine, checked in debug and sanitizer builds (SHOTLAB_CHECKS, set by CMake) and compiled out
// of release builds. A failure names the file, the line and the invariant, and aborts: it is a bug in the engine,
// never a consequence of input (input is refused with InputError before it reaches here).
#pragma once

#ifdef SHOTLAB_CHECKS
#include <cstdio>
#include <cstdlib>
#define SHOTLAB_ASSERT(condition, invariant)                                                             \
  do {                                                                                                   \
    if (!(condition)) {                                                                                  \
      std::fprintf(stderr, "%s:%d: engine invariant broken: %s (%s)\n", __FILE__, __LINE__, invariant, \
                   #condition);                                                                          \
      std::abort();                                                                                      \
    }                                                                                                    \
  } while (false)
#else
#define SHOTLAB_ASSERT(condition, invariant) ((void)0)
#endif
