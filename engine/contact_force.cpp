#include "contact_force.hpp"

namespace shotlab {

double sharpness_for(const Smoothing& s, double strength, double mobility) {
  const double rate = 1.5 * s.sharpness * strength * mobility;
  return s.rate_limit > 0 && rate > s.rate_limit ? s.sharpness * s.rate_limit / rate : s.sharpness;
}

double elastic_energy(const ContactMaterial& mat, double depth) {
  const double e = mat.exponent + 1;
  return mat.stiffness * (mat.exponent == 1.5 ? depth * depth * std::sqrt(depth) : std::pow(depth, e)) / e;
}

}  // namespace shotlab
