// Small vector vocabulary shared by the engine. Everything is SI: metres, seconds, kilograms, radians.
#pragma once
#include <glm/vec3.hpp>
#include <glm/geometric.hpp>
#include <algorithm>
#include <cmath>

namespace shotlab {

using Vec3 = glm::dvec3;

inline constexpr Vec3 kUp{0.0, 1.0, 0.0};

inline bool is_finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Unit vector of v, or zero when v has (numerically) no direction.
inline Vec3 unit_or_zero(const Vec3& v) {
  const double n = glm::length(v);
  return n > 1e-300 ? v / n : Vec3{0.0};
}

// Thesis appendix B: a smoothstep stretched to [-1, 1] that replaces sgn(f) in Coulomb friction.
// c = clamp(f,-1,1)/2 + 1/2 maps [-1,1] to [0,1]; the cubic 2c^2(3-2c) - 1 runs from -1 to 1 with zero slope at
// both ends and slope 1.5 at f = 0. Callers pass f = k * s, where k is the sharpness (1/unit of s).
inline double fricstep(double f) {
  const double c = std::clamp(f, -1.0, 1.0) * 0.5 + 0.5;
  return c * c * (3.0 - 2.0 * c) * 2.0 - 1.0;
}

}  // namespace shotlab
