// Sleeping (Box2D's islands, reduced to what billiards needs): a group of touching balls that has stayed at rest
// for sleep_time is frozen exactly (zero velocity, no equations integrated, no contacts evaluated), so resting balls
// cost nothing and cannot drift. A sleeping ball is an obstacle to awake ones; it wakes, with every sleeping ball
// touching it, as soon as an awake ball that is not at rest touches it. Contact onsets end the integrator's step
// (simulation.cpp), so a ball rolling into a sleeper wakes it at the instant of contact.
#pragma once
#include <vector>

#include "contacts.hpp"
#include "model.hpp"
#include "state.hpp"

namespace shotlab {

class Sleep {
 public:
  explicit Sleep(const Model& model) : model_(model), cache_(model) {}
  // After an accepted step of dt seconds ending at state x (state.asleep is updated, sleepers' velocities zeroed).
  // Returns true when a ball fell asleep or woke: the system changed and the integrator must restart.
  bool update(State& state, StateVector& x, double dt);

 private:
  bool at_rest(const State& state, const StateVector& x, int i) const;

  const Model& model_;
  ContactCache cache_;
  std::vector<double> still_for_;           // s each ball has been at rest
  std::vector<std::vector<int>> touching_;  // neighbours (frozen-touching included), rebuilt each update
};

}  // namespace shotlab
