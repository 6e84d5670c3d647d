// The rigid model's motion of a ball on the bed between events (docs/model.md#rigid-model): sliding, rolling and
// spinning at constant accelerations, so that position is a parabola in time and every change of kind has a closed-form
// time. The same laws as the soft model's regimes outside their friction bands (docs/model.md#sliding-to-rolling,
// #rolling-resistance, #spin-friction), with the friction switches taken as sharp.
#pragma once
#include <algorithm>
#include <limits>

#include "polynomial.hpp"
#include "shotlab/event.hpp"
#include "shotlab/vec.hpp"

namespace shotlab {

// The constants of one ball on the bed.
struct BedLaw {
  double radius;        // m
  double gravity;       // m/s^2, along -y
  double friction;      // sliding friction of the cloth
  double rolling;       // rolling resistance: deceleration rolling g
  double spin;          // spin friction: angular deceleration 5 spin g / (2 R) about the vertical
  double spin_decel() const { return 2.5 * spin * gravity / radius; }  // rad/s^2
};

// v in the bed's plane: its vertical part dropped.
inline Vec3 horizontal(const Vec3& v) { return {v.x, 0.0, v.z}; }

// Slip (m/s) and speed (m/s) under which a ball counts as rolling and as not moving after an impulse.
inline constexpr double kRigidSlip = 1e-9;
inline constexpr double kRigidSpeed = 1e-9;

// A ball's motion from t0 until `ends`, when its kind changes (+inf: never). y stays at p.y.
struct Track {
  double t0 = 0;         // s
  Vec3 p{0.0}, v{0.0}, w{0.0};  // m, m/s, rad/s at t0
  Motion kind = Motion::Stationary;  // Stationary, Spinning, Rolling, Sliding or Pocketed
  Vec3 accel{0.0};       // m/s^2, horizontal, constant while the kind lasts
  Vec3 spin_accel{0.0};  // rad/s^2 of the horizontal spin (sliding: the friction's torque; rolling: follows v)
  double ends = std::numeric_limits<double>::infinity();  // s
};

struct BallState {
  Vec3 p, v, w;  // m, m/s, rad/s
};

// The track of a ball with (p, v, w) at t0 on the bed: its kind from its slip and speed, its accelerations and when
// the kind ends. v.y is taken as 0 (the bed holds the ball).
Track bed_track(const BedLaw& law, double t0, const Vec3& p, const Vec3& v, const Vec3& w);
// A pocketed (or off-table) ball: frozen at p from t0.
Track out_track(double t0, const Vec3& p, Motion how);  // how: Pocketed or OffTable
// Where the ball is at time t in [t0, ends] of its track.
BallState at(const BedLaw& law, const Track& track, double t);
// The slip of the cloth contact (m/s): u = v + R y^ x w.
Vec3 bed_slip(double radius, const Vec3& v, const Vec3& w);

// The centre's horizontal path from time t on, as p + v s + accel s^2 / 2 in s = time - t.
struct Parabola {
  Vec3 p, v, a;
};
Parabola parabola(const BedLaw& law, const Track& track, double t);

// The box the centre on p stays inside over s in [0, h] (x and z; y is p.p.y).
struct Sweep {
  Vec3 lo, hi;  // m
  // Whether the segment a-b (a point when a = b) comes within `reach` of the box: else nothing on it can be touched.
  bool near(const Vec3& a, const Vec3& b, double reach) const {
    return std::min(a.x, b.x) - reach <= hi.x && std::max(a.x, b.x) + reach >= lo.x &&
           std::min(a.z, b.z) - reach <= hi.z && std::max(a.z, b.z) + reach >= lo.z;
  }
};
Sweep sweep(const Parabola& p, double h);

// The squared horizontal distance between two parabolas (x and z only) minus reach^2, as a polynomial in s.
Quartic gap_between(const Parabola& a, const Parabola& b, double reach);

}  // namespace shotlab
