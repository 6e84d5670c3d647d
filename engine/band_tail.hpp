// The tails of a regime ball's friction inside their smoothing bands, in closed form: the only parts of a rolling or
// sliding ball's motion that are not polynomial in time.
//
// Why it matters: a friction term stops the motion it opposes at a constant rate until that motion's speed q is
// within its band, |q| < 1/k (1 mm/s at k = 1000 s/m). There fricstep turns it into a damper that never quite stops
// it: q decays at about 1.5 A k (430 1/s for the spin about the normal, 150 1/s for the rolling speed), and an
// explicit method integrating that takes a dozen millisecond steps per tail, or a whole slide's worth where the band
// is entered while sliding. Each tail below keeps its direction, so it can be followed in closed form:
//  - Spin: the spin about the bed's normal, q = R w.n, in either regime. Nothing else in them reads w.n (the slip
//    and the rolling constraint involve n x w only) and spin friction reads nothing else.
//  - Speed: the speed of a rolling ball, q = |v|, against rolling resistance along the fixed direction of motion d;
//    the rolling constraint carries the spin along: w_t = n x v / R.
//  - Slip: the slip u = v + R n x w of a sliding ball about to roll, along its fixed direction u^ (rolling resistance
//    leaves the slip alone: its torque is made so, contact_force.hpp). Sliding friction changes the velocity by the
//    share s = (1/m) / (1/m + R^2/I) (2/7) of what it does to the slip, so v = v0 + s (q - q0) u^ + v_r; rolling
//    resistance, which acts inside the slip's band at the weight 1 - fricstep(k q) along the direction of v, brings
//    v_r = -a_r int (1 - fricstep) d dt (a_r: its deceleration at full weight). The friction turns that direction:
//    to first order d = d0 + s (q - q0) P u^ / |v0| (P: the part across d0), so
//      v_r = -a_r [(t - (q0 - q) / A) d0 + (s / |v0|) P u^ J],  J = int (1 - fricstep)(q - q0) = int q - q0 t + (q - q0)^2 / (2 A)
//    (the integral of fricstep(k q) is (q0 - q) / A, and of fricstep (q - q0) it is -(q - q0)^2 / (2 A)). What is left
//    out is second order in the turn (s q0 / |v0|, a few 1e-4 rad), and in the position the turn's own term (a_r times
//    the turn times t^2 / 2, 1e-11 m); the caller keeps both far under the tolerance. The spin follows from the slip:
//    w_t = (n x v - n x u) / R.
//
// Derivation (BandDecay). With A = (strength) x (mobility) (m/s^2, contact_force.hpp) and y = k q, |y| <= 1:
//   dq/dt = -A fricstep(k q),  fricstep(y) = y (3 - y^2) / 2      (vec.hpp's cubic, expanded on [-1, 1])
//   dy/dt = -(A k / 2) y (3 - y^2).
// For z = y^2, dz/dt = -A k z (3 - z), and u = 1/z obeys the linear du/dt = 3 A k u - A k, so with b = 3 A k,
// c = y0^2 / 3 and S(t) = sqrt(c + (1 - c) e^(b t)):
//   q(t) = q0 / S(t)                                   (q0 = 0 stays 0; an exponential that overflows gives 0)
// and, substituting s = S(t) (ds/dt = b (s^2 - c) / (2 s)) in the integral of 1 / S,
//   int_0^t q = q0 / (b sqrt(c)) [ln((s - sqrt c) / (s + sqrt c))]_{s=1}^{S(t)}.
#pragma once
#include <cmath>

#include "state.hpp"

namespace shotlab {

// q' = -A fricstep(k q) from q0 inside the band.
struct BandDecay {
  double q0;         // m/s, |k q0| <= 1
  double sharpness;  // k, s/m (as contact_force uses it: rate-limited, sharpness_for)
  double rate;       // A, m/s^2

  double at(double h) const { return q0 / root(h); }
  // m: int_0^h q, the logarithms written with log1p (accurate for the smallest q0).
  double integral(double h) const {
    const double y = sharpness * std::abs(q0), a = y / std::sqrt(3.0), b = 3.0 * rate * sharpness;
    if (a == 0) return 0.0;
    const double s = root(h);
    return std::copysign(std::sqrt(3.0) / (b * sharpness), q0) *
           (std::log1p(-2.0 * a / (s + a)) - std::log1p(-2.0 * a / (1.0 + a)));
  }
  // s: when |q| has fallen to q (0 < q <= |q0|): S(t) = |q0| / q solved for t.
  double time_to(double q) const {
    const double c = sharpness * sharpness * q0 * q0 / 3.0, s = std::abs(q0) / q;
    return std::log((s * s - c) / (1.0 - c)) / (3.0 * rate * sharpness);
  }

 private:
  double root(double h) const {
    const double c = sharpness * sharpness * q0 * q0 / 3.0;
    return std::sqrt(c + (1.0 - c) * std::exp(3.0 * rate * sharpness * h));
  }
};

struct BandTail {
  enum class Kind { Spin, Speed, Slip };
  Kind kind;
  int ball;         // in the state vector
  Vec3 normal;      // the bed's unit normal
  Vec3 direction;   // Speed: the unit direction of motion along the bed; Slip: the slip's, u^
  Vec3 start;       // Speed, Slip: the centre at the span's start, m
  double radius;    // m
  BandDecay decay;  // of q (m/s): R w.n, |v| or |u|
  Vec3 velocity{0.0};  // Slip: v0, m/s
  double rolling = 0;  // Slip: a_r, m/s^2
  double share = 0;    // Slip: s

  // Writes what the tail governs into its ball's 9 numbers [p, v, w] at `b`, h seconds into the span: Spin, w.n;
  // Speed and Slip, the position, the velocity and the tangential spin. The rest is left as it is.
  void apply(double h, double* b) const {
    const Vec3 w = spin(b, 0), wn = glm::dot(w, normal) * normal;
    const double q = decay.at(h);
    switch (kind) {
      case Kind::Spin:
        set_spin(b, 0, w - wn + (q / radius) * normal);
        return;
      case Kind::Speed:
        set_position(b, 0, start + decay.integral(h) * direction);
        set_velocity(b, 0, q * direction);
        set_spin(b, 0, wn + (q / radius) * glm::cross(normal, direction));
        return;
      case Kind::Slip: {
        // v as above; p its integral without the turn: v0 h + s (int q - q0 h) u^ - a_r (h^2 / 2 - (q0 h - int q) / A) d0.
        const double q0 = decay.q0, moved = decay.integral(h), A = decay.rate;
        Vec3 v = velocity + share * (q - q0) * direction, p = start + h * velocity + share * (moved - q0 * h) * direction;
        if (rolling > 0) {  // then v0 is not zero (the caller makes sure rolling resistance stays outside its band)
          const double speed = glm::length(velocity), J = moved - q0 * h + (q - q0) * (q - q0) / (2 * A);
          const Vec3 d = velocity / speed, across = direction - glm::dot(direction, d) * d;
          v -= rolling * ((h - (q0 - q) / A) * d + share / speed * J * across);
          p -= rolling * (0.5 * h * h - (q0 * h - moved) / A) * d;
        }
        set_position(b, 0, p);
        set_velocity(b, 0, v);
        set_spin(b, 0, wn + glm::cross(normal, v - q * direction) / radius);
        return;
      }
    }
  }
};

}  // namespace shotlab
