#include "rigid_collide.hpp"

#include <array>
#include <cmath>

namespace shotlab {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();
// Slices of a cushion impact's normal impulse; the error of the state after it falls as 1 / slices.
constexpr int kRailSlices = 64;

// The polynomial l0 + l1 s + l2 s^2 of a linear function `dir` . (x - origin) of the centre on p.
Quartic along(const Parabola& p, const Vec3& origin, const Vec3& dir) {
  return {glm::dot(p.p - origin, dir), glm::dot(p.v, dir), 0.5 * glm::dot(p.a, dir), 0.0, 0.0};
}

Quartic squared_minus(const Quartic& l, double reach) {
  return {l[0] * l[0] - reach * reach, 2 * l[0] * l[1], l[1] * l[1] + 2 * l[0] * l[2], 2 * l[1] * l[2], l[2] * l[2]};
}

// Friction impulse (N s) against the slip vt of a contact whose tangential compliance is `compliance` (s/kg): what
// stops the slip, at most `limit`; along -vt.
Vec3 friction_impulse(const Vec3& vt, double compliance, double limit) {
  const double slip = glm::length(vt);
  if (!(slip > 0)) return Vec3{0.0};
  return -std::min(limit, slip / compliance) * vt / slip;
}

}  // namespace

double point_entry(const Parabola& p, const Vec3& centre, double reach, double h) {
  return first_entry(gap_between(p, Parabola{centre, Vec3{0.0}, Vec3{0.0}}, reach), h);
}

double rail_entry(const Parabola& p, double radius, const Rail& rail, double h) {
  // In the bed's plane the capsule is a slab of half-width `reach` along the segment, capped by discs at its ends.
  const double dy = p.p.y - rail.a.y, full = radius + rail.radius;
  if (std::abs(dy) >= full) return kNever;
  const double reach = std::sqrt(full * full - dy * dy);
  const Vec3 seg = horizontal(rail.b - rail.a);
  const double length = glm::length(seg);
  const double first = std::min(point_entry(p, rail.a, reach, h), point_entry(p, rail.b, reach, h));
  if (!(length > 0)) return first;
  // Entries into the slab count where they are alongside the segment; a curved path may enter it twice.
  const Vec3 e = seg / length, n{-e.z, 0.0, e.x};
  std::array<double, 4> in{};
  const int count = entries(squared_minus(along(p, rail.a, n), reach), std::min(h, first), in);
  for (int k = 0; k < count; ++k) {
    const double lambda = evaluate(along(p, rail.a, e), in[k]);
    if (lambda >= 0 && lambda <= length) return std::min(first, in[k]);
  }
  return first;
}

double edge_exit(const Parabola& p, const Vec3& origin, const Vec3& u, const Vec3& v, double h) {
  double first = kNever;
  for (const Vec3& side : {u, v}) {
    const Quartic l = along(p, origin, side / glm::dot(side, side));  // 0 to 1 across the bed
    const Quartic far{1 - l[0], -l[1], -l[2], 0.0, 0.0};
    first = std::min({first, first_entry(l, h), first_entry(far, h)});
  }
  return first;
}

double closing_speed(const BallState& a, const BallState& b, const Vec3& n) { return glm::dot(a.v - b.v, n); }

double collide_balls(BallState& a, const BallSpec& ba, BallState& b, const BallSpec& bb, const Vec3& n,
                     const Bounce& bounce, const ContactMaterial& material) {
  // The event found them touching and not parting: a round-off negative closing speed counts as none.
  const double closing = std::max(0.0, closing_speed(a, b, n));
  const double jn = (closing + bounce.parting(closing)) / (1 / ba.mass + 1 / bb.mass);
  // The contact points' relative velocity (a's point at +R_a n, b's at -R_b n), less its normal part.
  const Vec3 vc = a.v + glm::cross(a.w, ba.radius * n) - b.v - glm::cross(b.w, -bb.radius * n);
  const Vec3 vt = vc - glm::dot(vc, n) * n;
  const double compliance = 1 / ba.mass + ba.radius * ba.radius / ba.inertia() + 1 / bb.mass +
                            bb.radius * bb.radius / bb.inertia();
  const Vec3 on_a = -jn * n + friction_impulse(vt, compliance, material.friction_at(glm::length(vt)) * jn);
  a.v += on_a / ba.mass, a.w += glm::cross(ba.radius * n, on_a) / ba.inertia();
  b.v -= on_a / bb.mass, b.w += glm::cross(-bb.radius * n, -on_a) / bb.inertia();
  a.v.y = b.v.y = 0;  // the bed takes any vertical part
  return closing;
}

Vec3 rail_normal(const BallState& k, const Rail& rail) {
  const Vec3 ab = rail.b - rail.a;
  const double along = glm::dot(ab, ab) > 0 ? std::clamp(glm::dot(k.p - rail.a, ab) / glm::dot(ab, ab), 0.0, 1.0) : 0;
  return glm::normalize(k.p - (rail.a + along * ab));
}

double collide_rail(BallState& k, const BallSpec& body, const Vec3& n, const Bounce& bounce, double friction,
                    double bed_friction) {
  const Vec3 nh = horizontal(n);
  if (!(glm::dot(nh, nh) > 0)) return 0;
  const double closing = std::max(0.0, -glm::dot(k.v, n));  // as in collide_balls
  // The impact integrated over the cushion's normal impulse, in slices (docs/model.md#rigid-model): in each, the
  // cushion's push along n, friction at its contact point against that point's slip, the bed's normal impulse that
  // holds the ball on the bed against the push's downward part (rails are not below a ball's centre:
  // rigid_unsupported), and the cloth's friction against the slip at the bed.
  const double across = glm::dot(nh, nh) / body.mass;  // (m/s) / (N s): speed along n a push gives
  const double slice = (closing + bounce.parting(closing)) / across / kRailSlices;  // N s
  const Vec3 at_rail = -body.radius * n, at_bed = -body.radius * kUp;
  const double compliance = 1 / body.mass + body.radius * body.radius / body.inertia();
  double taken = 0, given = 0;  // J: the push's work while the ball closes, and while it leaves
  auto done = [&] { return glm::dot(k.v, n) >= bounce.floor && given >= bounce.e * bounce.e * taken; };
  for (int s = 0; s < 4 * kRailSlices && !done(); ++s) {
    const double u = glm::dot(k.v, n);
    // A slice ends where the ball stops closing, or where the work and speed owed are paid.
    const double owed = std::max(0.0, bounce.e * bounce.e * taken - given);
    const double last = u < 0 ? -u / across
                              : std::max((std::sqrt(u * u + 2 * across * owed) - u) / across, (bounce.floor - u) / across);
    const double push = std::max(std::min(slice, last), 1e-3 * slice);
    Vec3 slip = k.v + glm::cross(k.w, at_rail);
    slip -= glm::dot(slip, n) * n;
    const Vec3 rub = friction_impulse(slip, compliance, friction * push);
    const double held = std::max(0.0, -(n.y * push + rub.y));  // N s
    const Vec3 rub_bed = friction_impulse(horizontal(k.v + glm::cross(k.w, at_bed)), compliance, bed_friction * held);
    k.v += (push * n + rub + held * kUp + rub_bed) / body.mass;
    k.w += (glm::cross(at_rail, rub) + glm::cross(at_bed, rub_bed)) / body.inertia();
    const double work = 0.5 * (u + glm::dot(k.v, n)) * push;  // trapezoid over the slice
    (u < 0 ? taken : given) += std::abs(work);
  }
  // Friction far beyond any cloth's can outlast the slices: the ball then leaves at the floor speed.
  if (const double short_by = bounce.floor - glm::dot(k.v, n); short_by > 0) k.v += short_by * nh / glm::dot(nh, nh);
  k.v.y = 0;
  return closing;
}

}  // namespace shotlab
