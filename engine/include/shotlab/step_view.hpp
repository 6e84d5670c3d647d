// What an observer of the stepping sees (Simulation::set_observer): one accepted step of one island, read-only.
// An island integrates some of the scene's balls on its own clock: ball k of the island is ball balls[k] of the
// scene, and its model and state hold only those balls (and every collider).
#pragma once
#include <vector>

#include "shotlab/model.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

struct Stats;
struct StepSpan;

class StepView {
 public:
  StepView(double t0, double t1, const std::vector<int>& balls, const Model& model, const State& state,
           const State& flags, const Stats& stats, const StepSpan& span)
      : t0(t0), t1(t1), balls(balls), model(model), state(state), flags(flags), stats(stats), span_(span) {}

  double t0, t1;                  // s: the step
  const std::vector<int>& balls;  // scene indices, ascending
  const Model& model;             // the island's model
  const State& state;             // the island's state at t1
  const State& flags;             // the regime flags the step ran with (a regime changes at a step's end; no x)
  const Stats& stats;             // the island's counts so far

  // The island's state vector at t in [t0, t1] from the step's dense output, written to x (resized).
  void state_at(double t, StateVector& x) const;

 private:
  const StepSpan& span_;
};

}  // namespace shotlab
