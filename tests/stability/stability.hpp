// Helpers of the stability suite, on top of the engine tests' helpers (scenes from inline JSON, presets, runs).
#pragma once
#include <cstdio>
#include <string>

#include "tests/engine/support.hpp"

namespace shotlab::test {

// The cost of a case, printed so that a regression in speed is visible in the CI log (timing goals belong in the
// bench, not in assertions).
inline void print_cost(const std::string& name, const Simulation& sim) {
  const Stats& s = sim.stats();
  std::printf("[ cost     ] %s: %.4g s simulated, %ld steps, %ld rejected, %ld rhs evaluations, %.3f s wall\n",
              name.c_str(), sim.time(), s.steps, s.rejected_steps, s.rhs_evaluations, s.wall_seconds);
}

// Advances from the current time to `until` (s) in frames of `frame` seconds (the last one shortened), calling
// check() after each frame; fails the test if the simulation stops (step limit, non-finite state, unstable).
template <class Check>
void run_frames(Simulation& sim, double until, double frame, Check check) {
  const double start = sim.time();
  const long frames = static_cast<long>(std::ceil((until - start) / frame - 1e-9));
  for (long k = 1; k <= frames; ++k) {
    ASSERT_EQ(sim.advance(std::min(start + k * frame, until) - sim.time()), Status::Ok) << sim.diagnostic();
    check();
  }
}

// Loads a bench scene (presets/bench/), with overrides.
inline Scene bench_scene(const std::string& file, const std::vector<std::string>& overrides = {}) {
  return load_scene(preset("bench/" + file), overrides);
}

}  // namespace shotlab::test
