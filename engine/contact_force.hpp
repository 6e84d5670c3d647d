// The contact force law (docs/model.md#normal-force, #friction): Hertz normal force with damping, Coulomb friction at
// the contact point, rolling resistance and spin friction. Used for every contact: ball-ball, ball-cloth, ball-cushion, any collider.
#pragma once
#include <cstdint>

#include "shotlab/contact.hpp"
#include "shotlab/material.hpp"
#include "shotlab/vec.hpp"

namespace shotlab {

// A contact normal known to point straight up, (0, 1, 0): the bed under a ball, a contact of every ball on the table
// in every right-hand side. On it the law's vector algebra reduces to components (the functions below): the same
// numbers, bar the sign of a zero, for a tenth less of a break's time.
struct UpNormal {};
inline double normal_component(const Vec3& a, const Vec3& n) { return glm::dot(a, n); }
inline double normal_component(const Vec3& a, UpNormal) { return a.y; }
inline Vec3 tangential_part(const Vec3& a, const Vec3& n) { return a - glm::dot(a, n) * n; }
inline Vec3 tangential_part(const Vec3& a, UpNormal) { return {a.x, 0.0, a.z}; }
inline Vec3 along_normal(double s, const Vec3& n) { return s * n; }
inline Vec3 along_normal(double s, UpNormal) { return {0.0, s, 0.0}; }
inline Vec3 normal_cross(const Vec3& n, const Vec3& a) { return glm::cross(n, a); }
inline Vec3 normal_cross(UpNormal, const Vec3& a) { return {a.z, 0.0, -a.x}; }

// Kinematics of one contact seen from ball A; the other body B is a ball or a static collider. Normal: Vec3, or
// UpNormal for the bed.
template <class Normal>
struct Kinematics {
  Normal normal;    // unit, from B towards A's centre
  double depth;     // penetration, m (> 0)
  Vec3 v_rel;       // velocity of A's centre minus B's, m/s
  Vec3 slip;        // velocity of A's surface point at the contact minus B's, m/s
  double spin_rel;  // (w_A - w_B) . normal, rad/s
  double radius;    // A's radius, m: the lever arm of spin friction
  // How fast each friction term changes the motion it opposes, per unit of force (1/kg): the slip at the contact
  // point (1/m + r^2/I of each ball: 3.5/m for a solid sphere), the relative centre velocity (1/m of each ball) and
  // the relative spin about the normal, as a surface speed r w (r^2/I of each ball). 0 for a static body.
  double slip_mobility;
  double velocity_mobility;
  double spin_mobility;
};
using ContactKinematics = Kinematics<Vec3>;

// What says which law a contact's friction follows: the FrictionBand bits, and each term (floats: what counts is their
// directions against each other's and the size of their change over a step). Kept for every contact at a step's ends
// (Dynamics::recorded).
struct FrictionState {
  FrictionState() = default;
  explicit FrictionState(const ContactForce& f)
      : friction(f.friction), rolling(f.rolling), spin_torque(static_cast<float>(f.spin_torque)), bands(f.bands) {}
  glm::vec3 friction{0.0f};  // N, ContactForce::friction
  glm::vec3 rolling{0.0f};   // N, ContactForce::rolling
  float spin_torque = 0;     // N m, ContactForce::spin_torque
  uint8_t bands = 0;         // FrictionBand bits
};

// Whether one contact's friction changed its law between two evaluations a and b that both push (normal > 0): a term
// entered or left its band, or had its width set by the rate limit or no longer, or turned its saturated force
// around (the motion it opposes went through the whole band in between). Such a kink inside an integrator step is
// what its error estimate misjudges: the island ends the step there (EventDetector::first_law_change).
bool friction_switched(const FrictionState& a, const FrictionState& b);
// Whether such a switch is only terms entering or leaving their bands. fricstep is C1 at its band's edge (its slope is
// 0 there, docs/model.md#fricstep), so the force keeps its first derivative through such a switch: a kink in the
// second, which costs a step that crosses it near its start far less than its error (EventDetector::first_law_change).
bool band_edges_only(const FrictionState& a, const FrictionState& b);

// Friction smoothing: the sharpness k of fricstep (s/m) and the largest rate (1/s) at which a smoothed friction term
// may relax the motion it opposes (Options::friction_rate_limit; 0: no limit).
struct Smoothing {
  double sharpness;
  double rate_limit;
};

// The sharpness (s/m) a friction term of the given strength (N) uses on a motion of the given mobility (1/kg).
// Inside its band (slip below 1/k) a friction term of strength F = mu N acts on the slip s it opposes like a linear
// damper: F fricstep(k s) ~ 1.5 k mu N s, which relaxes s at the rate lambda = 1.5 k mu N * mobility (1/s,
// docs/model.md#rate-limit). On the cloth (N = m g) that is about 1e4 1/s, but a hard impact presses a ball into a
// cushion or another ball with thousands of newtons, and lambda reaches 1e7 1/s: an explicit method then needs steps
// of 0.1 us for the whole contact, only to keep a stuck contact stuck. Above the rate limit the band widens instead
// (k drops to limit / (1.5 mu N mobility)): the contact still sticks within 1/limit seconds, a few microseconds,
// short against the contact's 0.2-1 ms, and the step stays set by the contact itself.
double sharpness_for(const Smoothing& s, double strength, double mobility);

// The normal force (N) of the law before its clamp, at the given depth (m, > 0) and approach rate (m/s): Hertz plus
// damping, negative while the damping pulls.
double normal_force(const ContactMaterial& mat, double depth, double rate);

// d/dt of normal_force along a path whose depth changes at `rate` (m/s) and whose rate changes at `accel` (m/s^2), in
// N/s: the bed's force over a bounce, interpolated to fifth order (bounce.cpp).
double normal_force_rate(const ContactMaterial& mat, double depth, double rate, double accel);
// N/m: the Hertz term's stiffness at the given depth (m, >= 0), d(C d^e)/dd = e C d^(e-1).
double hertz_stiffness(const ContactMaterial& mat, double depth);

// The elastic energy (J) stored in a contact at the given depth (m, > 0): the integral of the Hertz term,
// C d^(e+1) / (e+1).
double elastic_energy(const ContactMaterial& mat, double depth);

// With clamp = false the normal force is not clamped at zero and the tangential terms act at it, even a negative one:
// the smooth continuation of the law that a step takes up to where the force reaches zero (island.cpp), so that the
// clamp's kink does not fall inside a step.
template <class Normal>
ContactForce contact_force(const ContactMaterial& mat, const Kinematics<Normal>& k, const Smoothing& smoothing,
                           bool clamp = true);
// The tangential terms alone (friction, rolling resistance, spin friction) of a contact carrying the normal force
// out.normal > 0, added to `out`: contact_force's second half, and the whole bed force of a ball in the sliding
// regime (regimes.hpp), whose normal force is its weight.
template <class Normal>
void add_friction(const ContactMaterial& mat, const Kinematics<Normal>& k, const Smoothing& smoothing, ContactForce& out);

// The torque a contact force puts on a ball of radius r whose outward contact normal (centre to contact point) is
// -normal:  friction acts at r_c = -r n; rolling resistance comes with the torque (2/5) r n x F_roll, which keeps
// the slip unchanged (docs/model.md#rolling-resistance: alpha = (1/r) n x a and I = 2/5 m r^2); spin friction about n.
// tangential_torque is the first two alone.
inline Vec3 tangential_torque(const ContactForce& f, const Vec3& n, double r) {
  return glm::cross(-r * n, f.friction) + 0.4 * r * glm::cross(n, f.rolling);
}
inline Vec3 contact_torque(const ContactForce& f, const Vec3& n, double r) {
  return tangential_torque(f, n, r) + f.spin_torque * n;
}

}  // namespace shotlab

#include "contact_force_impl.hpp"
