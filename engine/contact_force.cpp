#include "contact_force.hpp"

namespace shotlab {

double sharpness_for(const Smoothing& s, double strength, double mobility) {
  const double rate = 1.5 * s.sharpness * strength * mobility;
  return s.rate_limit > 0 && rate > s.rate_limit ? s.sharpness * s.rate_limit / rate : s.sharpness;
}

bool friction_switched(const FrictionState& a, const FrictionState& b) {
  if (a.bands != b.bands) return true;
  // Turned around while saturated at both ends (inside the band a term is smooth through zero, and a resting contact's
  // round-off turns it every which way).
  return (!(a.bands & kSlipInBand) && glm::dot(a.friction, b.friction) < 0) ||
         (!(a.bands & kRollInBand) && glm::dot(a.rolling, b.rolling) < 0) ||
         (!(a.bands & kSpinInBand) && a.spin_torque * b.spin_torque < 0);
}

double elastic_energy(const ContactMaterial& mat, double depth) {
  const double e = mat.exponent + 1;
  return mat.stiffness * (mat.exponent == 1.5 ? depth * depth * std::sqrt(depth) : std::pow(depth, e)) / e;
}

}  // namespace shotlab
