// Bodies of the contact law (contact_force.hpp), inline; not for direct inclusion. The right-hand side calls them for
// every contact, and inlined into its contact loop it runs a third faster (the rack's right-hand side, 16 balls and 36
// contacts: 2.3 -> 1.6 us); link-time optimisation did not inline them.
#pragma once
#include <cmath>

namespace shotlab {

namespace contact_law {

// fricstep(k q) with k = sharpness_for(s, strength, mobility), without sharpness_for's division where the term is
// saturated (|k q| >= 1: a sliding contact, the common case in this innermost loop). Rate-limited, k q is
// sharpness limit q / rate, at least 1 exactly where sharpness limit |q| >= rate.
inline double smoothed_sign(const Smoothing& s, double strength, double mobility, double q) {
  const double rate = 1.5 * s.sharpness * strength * mobility;
  if (s.rate_limit > 0 && rate > s.rate_limit) {
    if (s.sharpness * s.rate_limit * std::abs(q) >= rate) return q > 0 ? 1.0 : -1.0;
    return fricstep(s.sharpness * s.rate_limit / rate * q);
  }
  return fricstep(s.sharpness * q);
}

}  // namespace contact_law

inline double normal_force(const ContactMaterial& mat, double depth, double rate) {
  // Hertz's exponent 1.5 as d sqrt(d): std::pow costs several times more in this innermost loop.
  const double elastic = mat.stiffness * (mat.exponent == 1.5 ? depth * std::sqrt(depth) : std::pow(depth, mat.exponent));
  return mat.damping_law == DampingLaw::Linear ? elastic + mat.damping * rate : elastic * (1.0 + mat.damping * rate);
}

inline ContactForce contact_force(const ContactMaterial& mat, const ContactKinematics& k, const Smoothing& smoothing,
                                  bool clamp) {
  ContactForce out;
  const double fn = normal_force(mat, k.depth, -glm::dot(k.v_rel, k.normal));  // d' > 0 while the bodies approach
  // Clamp: the damping term turns negative while the bodies separate; a contact can push but never pull.
  out.normal = clamp ? std::max(fn, 0.0) : fn;
  out.force = out.normal * k.normal;
  if (out.normal > 0.0 || !clamp) add_friction(mat, k, smoothing, out);
  return out;
}

inline void add_friction(const ContactMaterial& mat, const ContactKinematics& k, const Smoothing& smoothing,
                         ContactForce& out) {
  const Vec3& n = k.normal;
  // Coulomb friction against the tangential slip, its sign smoothed by fricstep (MODEL.md appendix B).
  const Vec3 u = k.slip - glm::dot(k.slip, n) * n;
  const double u_len = glm::length(u);
  // slide: 0 at no slip, 1 once slip > 1/k
  const double slide = contact_law::smoothed_sign(smoothing, mat.friction * out.normal, k.slip_mobility, u_len);
  if (mat.friction > 0 && u_len > 0) {
    out.friction = -(mat.friction * out.normal * slide / u_len) * u;
    out.force += out.friction;
  }
  // Rolling resistance: only while (nearly) rolling, i.e. weighted by 1 - slide (0 on a sliding contact: skipped),
  // against the tangential motion.
  if (mat.rolling_resistance > 0 && slide < 1.0) {
    const Vec3 vt = k.v_rel - glm::dot(k.v_rel, n) * n;
    const double vt_len = glm::length(vt);
    if (vt_len > 0) {
      const double strength = mat.rolling_resistance * out.normal;
      const double mag =
          strength * contact_law::smoothed_sign(smoothing, strength, k.velocity_mobility, vt_len) * (1.0 - slide);
      out.rolling = -(mag / vt_len) * vt;
      out.force += out.rolling;
    }
  }
  // Spin friction about the normal; the contact patch speed r*w sets the smoothing, like any slip.
  if (mat.spin_friction > 0) {
    const double strength = mat.spin_friction * out.normal;  // the torque over the lever arm r, N
    out.spin_torque =
        -strength * k.radius * contact_law::smoothed_sign(smoothing, strength, k.spin_mobility, k.radius * k.spin_rel);
  }
}

}  // namespace shotlab
