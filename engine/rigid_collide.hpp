// The rigid model's collisions (docs/model.md#rigid-model): when a ball on its parabola first meets another ball, a
// cushion or jaw, a pocket's hole or the bed's edge, and the impulses that change the balls' velocities and spins at
// that instant.
#pragma once
#include <algorithm>

#include "rigid_motion.hpp"
#include "shotlab/material.hpp"
#include "shotlab/model.hpp"

namespace shotlab {

// A cushion or jaw: a horizontal capsule (table.hpp) with its axis from a to b at height a.y.
struct Rail {
  int collider;
  Vec3 a, b;      // m
  double radius;  // m, of the capsule
};

// s in [0, h]: when a ball of `radius` on parabola `p` (centre at height p.p.y) first touches the rail; +inf when not.
double rail_entry(const Parabola& p, double radius, const Rail& rail, double h);
// s in [0, h]: when the centre on `p` first comes within `reach` of `centre` in the bed's plane; +inf when not.
double point_entry(const Parabola& p, const Vec3& centre, double reach, double h);
// s in [0, h]: when the centre on `p` first leaves the parallelogram origin + [0, 1] u + [0, 1] v (horizontal u, v).
double edge_exit(const Parabola& p, const Vec3& origin, const Vec3& u, const Vec3& v, double h);

// How a collision parts two bodies: by restitution e, and at no less than `floor` m/s, so that a touching pair that
// closes slowly, or not at all but accelerating together, moves apart.
struct Bounce {
  double e;
  double floor;  // m/s
  double parting(double closing) const { return std::max(e * closing, floor); }  // m/s, from the closing m/s
};

// Two balls touching with unit horizontal normal n from a to b, a closing on b (or touching): the normal impulse that
// parts them at bounce.parting(closing), and a friction impulse against the slip of their contact points, at most
// material.friction_at(slip) times the normal one (then it stops the slip). Both stay on the bed: no vertical speed.
// Returns the closing speed (m/s).
double collide_balls(BallState& a, const BallSpec& ba, BallState& b, const BallSpec& bb, const Vec3& n,
                     const Bounce& bounce, const ContactMaterial& material);
// The closing speed (m/s) along n of a's centre on b's.
double closing_speed(const BallState& a, const BallState& b, const Vec3& n);

// A ball touching a rail: the unit normal from the nearest point of the rail's axis to the ball's centre.
Vec3 rail_normal(const BallState& k, const Rail& rail);
// A ball closing on (or touching) a rail with normal n, integrated over the impact's normal impulse: the cushion's
// push along n, friction at its contact point up to `friction` times the push, and, at the same time, the bed's normal
// impulse that holds the ball on the bed and the cloth's friction up to `bed_friction` times it; until the push has
// given back e^2 times the work it took while the ball closed (energetic restitution: friction cannot make it gain
// energy) and the ball leaves at bounce.floor m/s or more along n. Returns the closing speed (m/s).
double collide_rail(BallState& k, const BallSpec& body, const Vec3& n, const Bounce& bounce, double friction,
                    double bed_friction);

}  // namespace shotlab
