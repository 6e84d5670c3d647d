#include "contact_force.hpp"

namespace shotlab {

double sharpness_for(const Smoothing& s, double strength, double mobility) {
  const double rate = 1.5 * s.sharpness * strength * mobility;
  return s.rate_limit > 0 && rate > s.rate_limit ? s.sharpness * s.rate_limit / rate : s.sharpness;
}

namespace {

// A term saturated at both ends whose force turned around (inside the band a term is smooth through zero, and a
// resting contact's round-off turns it every which way).
bool turned_around(const FrictionState& a, const FrictionState& b) {
  return (!(a.bands & kSlipInBand) && glm::dot(a.friction, b.friction) < 0) ||
         (!(a.bands & kRollInBand) && glm::dot(a.rolling, b.rolling) < 0) ||
         (!(a.bands & kSpinInBand) && a.spin_torque * b.spin_torque < 0);
}

}  // namespace

bool friction_switched(const FrictionState& a, const FrictionState& b) {
  return a.bands != b.bands || turned_around(a, b);
}

bool band_edges_only(const FrictionState& a, const FrictionState& b) {
  const unsigned changed = a.bands ^ b.bands;
  constexpr unsigned kInBand = kSlipInBand | kRollInBand | kSpinInBand;
  // A term's limited bit may change only with its in-band bit (it is set inside the band alone).
  return (changed >> 3 & ~changed & kInBand) == 0 && !turned_around(a, b);
}

double hertz_stiffness(const ContactMaterial& mat, double depth) {
  return mat.exponent * mat.stiffness * (mat.exponent == 1.5 ? std::sqrt(depth) : std::pow(depth, mat.exponent - 1.0));
}

double normal_force_rate(const ContactMaterial& mat, double depth, double rate, double accel) {
  const double stiffening = hertz_stiffness(mat, depth) * rate;
  return mat.damping_law == DampingLaw::Linear
             ? stiffening + mat.damping * accel
             : stiffening * (1.0 + mat.damping * rate) + normal_force(mat, depth, 0.0) * mat.damping * accel;
}

double elastic_energy(const ContactMaterial& mat, double depth) {
  const double e = mat.exponent + 1;
  return mat.stiffness * (mat.exponent == 1.5 ? depth * depth * std::sqrt(depth) : std::pow(depth, e)) / e;
}

}  // namespace shotlab
