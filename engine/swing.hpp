// The swing: a ball alone on its rod, touching nothing, moves as an ideal plane pendulum in closed form (Jacobi's
// elliptic functions), so an island of such balls steps without an integrator and a Newton's cradle's balls arrive at
// their next contact within round-off (docs/model.md#swing).
#pragma once
#include <optional>

#include "shotlab/state.hpp"

namespace shotlab {

struct Model;
struct ModelIndex;

struct Swing {
  int ball;          // in the state vector
  Vec3 anchor;       // A, m
  Vec3 down;         // ĝ
  Vec3 across;       // ê: horizontal, in the plane of the swing
  double length;     // L, m
  double omega;      // ω0, rad/s
  double modulus;    // k = sin(amplitude / 2), 0 <= k < 1
  double phase;      // u0 (dimensionless)

  // Writes the ball's position and velocity h seconds into the span into its 9 numbers [p, v, w] at `b` (the spin
  // is left as it is: it does not change).
  void apply(double h, double* b) const;
};

// The swing of ball i at x (an island's state vector), if it has one: the model asks for it (Options::swing_regime),
// the ball hangs on exactly one rod and touches no ball and no collider within contact_margin, and gravity acts; the
// ball is at the rod's length and moving across it, and in the vertical plane through it, to within a share of the
// absolute tolerance (the closed form starts from the ball put exactly there); and it swings no higher than the
// anchor (90 degrees), where free_acceleration's bound of 2 |g| (contacts.hpp) still holds for the step cap.
// `last`: the swing the ball followed over the step that ended at x, its phase moved on to that end (or none). Where x
// is exactly where it led, the ball goes on with it, skipping the elliptic integral that finds the phase afresh.
std::optional<Swing> swing_of(const Model& model, const State& state, const ModelIndex& index, const double* x, int i,
                              const Swing* last = nullptr);

}  // namespace shotlab
