// The swing: a ball alone on its rod, touching nothing, moves as an ideal plane pendulum, whose motion has a closed
// form (regimes.hpp's other closed forms are on the bed). An island of such balls (and of balls asleep, rolling or
// sliding) steps without an integrator: one step as long as the caps allow, exact at every point of it, ended where
// a contact begins. A Newton's cradle's balls swing so between their contacts.
//
// Why it matters: integrated, a swing is a smooth arc that an adaptive method crosses in a few dozen steps, each
// with an error of up to the tolerance, and the chain of contacts that follows carries the arrival's error into every
// ball after it (S5: the cradle's first ball, 45 steps, arrived 2.7e-9 m off and made five times the plain path's
// error at the end; the plain path's steps were held to 1 ms by its resting balls' gaps). In closed form it arrives
// within round-off.
//
// Derivation. Gravity g (unit ĝ = g/|g|) and the rod's force (dynamics.cpp: along the rod, whatever keeps |p - A| = L)
// are the only forces on a ball that touches nothing; the rod's force passes through the centre, so the spin stays as
// it is. If the velocity lies in the vertical plane through the rod, so does the motion: with θ the angle from ĝ
// towards ê (the plane's horizontal unit vector), p = A + L (cos θ ĝ + sin θ ê), and θ'' = -ω0^2 sin θ with
// ω0^2 = |g| / L. Its energy integral gives, for a swing that turns back (the modulus k < 1),
//   k^2 = sin^2(θ0 / 2) + (θ'0 / (2 ω0))^2,   sin(θ / 2) = k sn(u, k),   θ' = 2 k ω0 cn(u, k),   u = u0 + ω0 t,
// (differentiating, (1/2) cos(θ/2) θ' = k ω0 cn dn, and cos(θ/2) = dn since 1 - k^2 sn^2 = dn^2), where sn, cn, dn
// are Jacobi's elliptic functions and the phase u0 is F(φ0, k), Legendre's incomplete integral of the first kind at
// the amplitude φ0 with sin φ0 = sin(θ0/2) / k and cos φ0 = θ'0 / (2 k ω0).
#pragma once
#include <optional>

#include "state.hpp"

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
