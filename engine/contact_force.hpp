// The contact force law (MODEL.md ch. 4): Hertz normal force with damping, Coulomb friction at the contact point,
// rolling resistance and spin friction. Used for every contact: ball-ball, ball-cloth, ball-cushion, any collider.
#pragma once
#include "material.hpp"
#include "vec.hpp"

namespace shotlab {

// Kinematics of one contact seen from ball A; the other body B is a ball or a static collider.
struct ContactKinematics {
  Vec3 normal;      // unit, from B towards A's centre
  double depth;     // penetration, m (> 0)
  Vec3 v_rel;       // velocity of A's centre minus B's, m/s
  Vec3 slip;        // velocity of A's surface point at the contact minus B's, m/s
  double spin_rel;  // (w_A - w_B) . normal, rad/s
  double radius;    // A's radius, m: the lever arm of spin friction
};

struct ContactForce {
  double normal = 0;       // |F_n|, N (clamped at >= 0)
  Vec3 force{0.0};         // total force on A's centre, N (B gets the opposite)
  Vec3 friction{0.0};      // the sliding-friction part of `force`, acting at the contact point, N
  Vec3 rolling{0.0};       // the rolling-resistance part of `force`, N
  double spin_torque = 0;  // torque on A about the normal, N m (B gets the opposite)
};

ContactForce contact_force(const ContactMaterial& mat, const ContactKinematics& k, double sharpness);

// The torque a contact force puts on a ball of radius r whose outward contact normal (centre to contact point) is
// -normal:  friction acts at r_c = -r n; rolling resistance comes with the torque (2/5) r n x F_roll, which keeps
// the slip unchanged (MODEL.md eq. 3.7: alpha = (1/r) n x a and I = 2/5 m r^2); spin friction about n.
inline Vec3 contact_torque(const ContactForce& f, const Vec3& n, double r) {
  return glm::cross(-r * n, f.friction) + 0.4 * r * glm::cross(n, f.rolling) + f.spin_torque * n;
}

}  // namespace shotlab
