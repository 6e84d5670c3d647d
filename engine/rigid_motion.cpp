#include "rigid_motion.hpp"

#include <cmath>

namespace shotlab {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// s after which a rate `rate` takes `amount` to zero; never without a rate.
double lasts(double amount, double rate) { return rate > 0 ? amount / rate : kNever; }

}  // namespace

Vec3 bed_slip(double radius, const Vec3& v, const Vec3& w) { return v + radius * glm::cross(kUp, w); }

Track bed_track(const BedLaw& law, double t0, const Vec3& p, const Vec3& v_in, const Vec3& w) {
  Track t;
  t.t0 = t0, t.p = p, t.v = horizontal(v_in), t.w = w;
  const Vec3 u = horizontal(bed_slip(law.radius, t.v, w));
  const double slip = glm::length(u), speed = glm::length(t.v);
  if (slip > kRigidSlip) {  // docs/model.md#sliding-to-rolling: the slip keeps its direction and falls at 7/2 mu g
    const Vec3 along = u / slip;
    t.kind = Motion::Sliding;
    t.accel = -law.friction * law.gravity * along;
    t.spin_accel = 2.5 * law.friction * law.gravity / law.radius * glm::cross(kUp, along);
    t.ends = t0 + lasts(slip, 3.5 * law.friction * law.gravity);
  } else if (speed > kRigidSpeed) {  // docs/model.md#rolling-resistance: constant deceleration mu_r g, no slip
    t.kind = Motion::Rolling;
    t.w = glm::cross(kUp, t.v) / law.radius + w.y * kUp;
    t.accel = -law.rolling * law.gravity * t.v / speed;
    t.spin_accel = glm::cross(kUp, t.accel) / law.radius;
    t.ends = t0 + lasts(speed, law.rolling * law.gravity);
  } else if (std::abs(w.y) * law.radius > kRigidSpeed) {
    t.kind = Motion::Spinning;
    t.v = Vec3{0.0}, t.w = w.y * kUp;
    t.ends = t0 + lasts(std::abs(w.y), law.spin_decel());
  } else {
    t.kind = Motion::Stationary;
    t.v = Vec3{0.0}, t.w = Vec3{0.0};
  }
  return t;
}

Track out_track(double t0, const Vec3& p, Motion how) {
  Track t;
  t.t0 = t0, t.p = p, t.kind = how;
  return t;
}

BallState at(const BedLaw& law, const Track& track, double t) {
  const double s = std::max(0.0, std::min(t, track.ends) - track.t0);
  BallState k{track.p + track.v * s + 0.5 * s * s * track.accel, track.v + s * track.accel,
               track.w + s * track.spin_accel};
  // The spin about the vertical falls linearly to zero in every kind (docs/model.md#spin-friction).
  const double wy = std::abs(track.w.y) - law.spin_decel() * s;
  k.w.y = wy > 0 ? std::copysign(wy, track.w.y) : 0.0;
  if (out_of_play(track.kind)) k.v = k.w = Vec3{0.0};
  return k;
}

Parabola parabola(const BedLaw& law, const Track& track, double t) {
  const BallState k = at(law, track, t);
  return {k.p, k.v, track.accel};
}

Sweep sweep(const Parabola& p, double h) {
  Sweep box{p.p, p.p};
  for (int axis : {0, 2}) {
    auto x = [&](double s) { return p.p[axis] + p.v[axis] * s + 0.5 * p.a[axis] * s * s; };
    double lo = std::min(x(0), x(h)), hi = std::max(x(0), x(h));
    const double turn = p.a[axis] != 0 ? -p.v[axis] / p.a[axis] : -1;  // where the axis' speed changes sign
    if (turn > 0 && turn < h) lo = std::min(lo, x(turn)), hi = std::max(hi, x(turn));
    box.lo[axis] = lo, box.hi[axis] = hi;
  }
  return box;
}

Quartic gap_between(const Parabola& a, const Parabola& b, double reach) {
  return squared_gap(horizontal(b.p - a.p), horizontal(b.v - a.v), horizontal(b.a - a.a), reach);
}

}  // namespace shotlab
