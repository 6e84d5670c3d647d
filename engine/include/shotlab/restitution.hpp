// Restitution as a setting (docs/model.md#restitution): the damping, and if asked the stiffness, that give a head-on
// impact a wanted restitution and contact time. Worked out on the normal law scaled to one dimensionless parameter,
// so it holds for any masses and stiffnesses, and costs milliseconds.
#pragma once
#include <string>

#include "shotlab/material.hpp"

namespace shotlab {

// A head-on impact of the normal law alone, in units of the undamped law's depth and time scales: starting at depth 0
// with unit approach speed under x'' = -x^n - g x' (linear damping, g = C_d T / m_eff) or x'' = -x^n (1 + g x')
// (Hunt-Crossley, g = C_d v), the force clamped at zero. T = (m_eff v^2 / C_s)^(1 / (n + 1)) / v.
struct ScaledImpact {
  double restitution = 0;  // separation speed over approach speed; 0 when the bodies never part
  double duration = 0;     // from touching to parting, in units of T
};
ScaledImpact scaled_impact(DampingLaw law, double exponent, double g);

// m_eff (kg) of the impacts a material serves: two equal balls of mass m for ball_ball (m / 2), else m.
double effective_mass(bool ball_ball, double ball_mass);

// The restitution of a head-on impact at closing speed v (m/s) between bodies of effective mass m_eff (kg) under the
// material's normal law, damping and clamp as they are: what the rigid model's impulses use (docs/model.md#rigid-model).
// Interpolated in the log of the scaled damping g between values of scaled_impact, built into the engine for Hertz
// contacts and worked out once per process otherwise (thread-safe): within 1e-5 of scaled_impact at g itself.
double restitution_at(const ContactMaterial& material, double m_eff, double v);

// Sets material.damping (and, when material.contact_time > 0, material.stiffness) so that a head-on impact at
// material.restitution_speed between bodies of effective mass m_eff has restitution material.restitution and lasts
// material.contact_time. Returns an empty string, or what makes it impossible (restitution outside (0, 1], a speed or
// time not positive); the material is then left as it was.
std::string apply_restitution(ContactMaterial& material, double m_eff);

// The damping that gives the material restitution e at impact speed v (m/s) for effective mass m_eff, its stiffness
// kept; the material's own damping when e is out of range.
double damping_for_restitution(const ContactMaterial& material, double m_eff, double v, double e);

// Switches the material's damping law keeping its restitution at impact speed v (m/s) for effective mass m_eff: the
// two laws' damping coefficients differ in meaning and unit (N s/m against s/m), so the number cannot be kept. Where
// the old restitution is out of reach (an overdamped contact), the damping number is left as it was: returns false.
bool switch_damping_law(ContactMaterial& material, DampingLaw law, double m_eff, double v);

}  // namespace shotlab
