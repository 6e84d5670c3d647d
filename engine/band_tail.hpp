// The tails of a regime ball's friction inside their smoothing bands, in closed form: the only parts of a rolling or
// sliding ball's motion that are not polynomial in time. Inside its band a friction term is a damper that would hold
// an explicit method to millisecond steps; each tail keeps its direction, so it is followed exactly instead: the spin
// about the bed's normal, a rolling ball's speed, a sliding ball's slip. Derivation: docs/model.md#band-tails.
#pragma once
#include <cmath>

#include "shotlab/state.hpp"

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
