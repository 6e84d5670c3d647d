// A contact as programs see it: the bodies, the depth and where, and the force of the law on it (contact_force.hpp).
#pragma once
#include <cstdint>

#include "shotlab/vec.hpp"

namespace shotlab {

// Where a contact's friction terms act (ContactForce::bands). Each term is Coulomb friction of constant strength
// while the motion it opposes is beyond its smoothing band (|k q| >= 1) and a stiff linear damper inside it; at the
// band's edge its force has a kink, and so has a term inside its band where the rate limit starts to set its width.
enum FrictionBand : uint8_t {
  kSlipInBand = 1,   // sliding friction, against the slip at the contact point
  kRollInBand = 2,   // rolling resistance, against the relative velocity of the centres
  kSpinInBand = 4,   // spin friction, against the relative spin about the normal
  kSlipLimited = 8,  // ... inside the band and widened by the rate limit (Smoothing::rate_limit)
  kRollLimited = 16,
  kSpinLimited = 32,
};

struct ContactForce {
  double normal = 0;       // |F_n|, N (clamped at >= 0)
  Vec3 force{0.0};         // total force on A's centre, N (B gets the opposite)
  Vec3 friction{0.0};      // the sliding-friction part of `force`, acting at the contact point, N
  Vec3 rolling{0.0};       // the rolling-resistance part of `force`, N
  double spin_torque = 0;  // torque on A about the normal, N m (B gets the opposite)
  uint8_t bands = 0;       // FrictionBand bits of the terms that act
};

struct Contact {
  int ball;          // ball A
  int other_ball;    // ball B, or -1 when B is a collider
  int collider;      // collider index, or -1 when B is a ball
  double depth;      // m
  Vec3 normal;       // unit, from B towards A
  Vec3 point;        // contact point (on A's surface), m
  ContactForce force;  // on A
};

}  // namespace shotlab
