// Read-only measurements of a state: energy, momentum, the list of live contacts with their forces.
#pragma once
#include <vector>

#include "shotlab/contact.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

struct Energy {
  double kinetic = 0;    // J, translation + rotation
  double potential = 0;  // J, gravity, zero at the origin
  double elastic = 0;    // J, stored in Hertz contacts: integral of C_s d^m = C_s d^(m+1) / (m+1)
  double total() const { return kinetic + potential + elastic; }
};

// One ball's part: kinetic energy of translation and of rotation (J), momentum (kg m/s).
struct BallMotion {
  double translation = 0, rotation = 0;
  Vec3 momentum{0.0};
};
BallMotion ball_motion(const Model& model, const State& state, int ball);

Energy energy(const Model& model, const State& state);
Vec3 momentum(const Model& model, const State& state);  // kg m/s, balls in play
std::vector<Contact> contacts(const Model& model, const State& state);

}  // namespace shotlab
