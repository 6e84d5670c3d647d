// Bodies of the contact law (contact_force.hpp), inline; not for direct inclusion. The right-hand side calls them for
// every contact: always_inline, since with several callers GCC stops inlining them and the contact loop slows.
#pragma once
#include <cmath>

namespace shotlab {

namespace contact_law {

// fricstep(k q) with k = sharpness_for(s, strength, mobility), without sharpness_for's division where the term is
// saturated (|k q| >= 1: a sliding contact, the common case in this innermost loop). Rate-limited, k q is
// sharpness limit q / rate, at least 1 exactly where sharpness limit |q| >= rate. Inside the band (the result is
// then under 1 in magnitude: fricstep is exactly +-1 outside) the term's FrictionBand bits go to `bands`: in_band,
// and `limited` where the rate limit sets the band.
inline double smoothed_sign(const Smoothing& s, double strength, double mobility, double q, uint8_t& bands,
                            uint8_t in_band, uint8_t limited) {
  const double rate = 1.5 * s.sharpness * strength * mobility;
  double sign;
  if (s.rate_limit > 0 && rate > s.rate_limit) {
    if (s.sharpness * s.rate_limit * std::abs(q) >= rate) return q > 0 ? 1.0 : -1.0;
    sign = fricstep(s.sharpness * s.rate_limit / rate * q);
    if (std::abs(sign) < 1.0) bands |= in_band | limited;
  } else {
    sign = fricstep(s.sharpness * q);
    if (std::abs(sign) < 1.0) bands |= in_band;
  }
  return sign;
}

}  // namespace contact_law

inline double normal_force(const ContactMaterial& mat, double depth, double rate) {
  // Hertz's exponent 1.5 as d sqrt(d): std::pow costs several times more in this innermost loop.
  const double elastic = mat.stiffness * (mat.exponent == 1.5 ? depth * std::sqrt(depth) : std::pow(depth, mat.exponent));
  return mat.damping_law == DampingLaw::Linear ? elastic + mat.damping * rate : elastic * (1.0 + mat.damping * rate);
}

template <class Normal>
[[gnu::always_inline]] inline ContactForce contact_force(const ContactMaterial& mat, const Kinematics<Normal>& k,
                                                         const Smoothing& smoothing, bool clamp) {
  ContactForce out;
  const double fn = normal_force(mat, k.depth, -normal_component(k.v_rel, k.normal));  // d' > 0 while approaching
  // Clamp: the damping term turns negative while the bodies separate; a contact can push but never pull.
  out.normal = clamp ? std::max(fn, 0.0) : fn;
  out.force = along_normal(out.normal, k.normal);
  if (out.normal > 0.0 || !clamp) add_friction(mat, k, smoothing, out);
  return out;
}

template <class Normal>
[[gnu::always_inline]] inline void add_friction(const ContactMaterial& mat, const Kinematics<Normal>& k,
                                                const Smoothing& smoothing, ContactForce& out) {
  // Coulomb friction against the tangential slip, its sign smoothed by fricstep (docs/model.md#fricstep).
  const Vec3 u = tangential_part(k.slip, k.normal);
  const double u_len = glm::length(u);
  // slide: 0 at no slip, 1 once slip > 1/k
  // A frictionless contact has no law to switch: its band bits stay clear.
  uint8_t slip_bands = 0;
  const double mu = mat.friction_at(u_len);
  const double slide =
      contact_law::smoothed_sign(smoothing, mu * out.normal, k.slip_mobility, u_len, slip_bands, kSlipInBand, kSlipLimited);
  if (mu > 0) out.bands |= slip_bands;
  if (mu > 0 && u_len > 0) {
    out.friction = -(mu * out.normal * slide / u_len) * u;
    out.force += out.friction;
  }
  // Rolling resistance: only while (nearly) rolling, i.e. weighted by 1 - slide (0 on a sliding contact: skipped),
  // against the tangential motion.
  if (mat.rolling_resistance > 0 && slide < 1.0) {
    const Vec3 vt = tangential_part(k.v_rel, k.normal);
    const double vt_len = glm::length(vt);
    const double strength = mat.rolling_resistance * out.normal;
    // The sign also at rest, inside its band there: the band bits of a resting contact and of one moving at 1e-20 m/s
    // are the same.
    const double sign =
        contact_law::smoothed_sign(smoothing, strength, k.velocity_mobility, vt_len, out.bands, kRollInBand, kRollLimited);
    if (vt_len > 0) {
      out.rolling = -(strength * (1.0 - slide) * sign / vt_len) * vt;
      out.force += out.rolling;
    }
  }
  // Spin friction about the normal; the contact patch speed r*w sets the smoothing, like any slip.
  if (mat.spin_friction > 0) {
    const double strength = mat.spin_friction * out.normal;  // the torque over the lever arm r, N
    out.spin_torque = -strength * k.radius * contact_law::smoothed_sign(smoothing, strength, k.spin_mobility,
                                                                        k.radius * k.spin_rel, out.bands, kSpinInBand, kSpinLimited);
  }
}

}  // namespace shotlab
