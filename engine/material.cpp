#include "shotlab/material.hpp"

namespace shotlab {

// Phenolic resin, E = 5.6 GPa, nu = 0.34: E* = E / (2 (1 - nu^2)) = 3.17 GPa; two pool balls (R_eff = R/2):
// C_s = 4/3 E* sqrt(R/2) = 5.0e8 N/m^1.5. Linear damping 20 N s/m gives the dimensionless damping
// zeta = C_d m_eff^-0.6 C_s^-0.4 v^-0.2 = 0.029 at 1 m/s, i.e. restitution 0.95 (VALIDATION.md R6).
// Friction falls with the slip speed u: mu(u) = a + b exp(-c u), a = 0.00995, b = 0.108, c = 1.088 s/m, Alciatore's
// fit to Marlow's measurements (docs/model.md#friction-speed), as friction = a + b and a fast ratio a / (a + b).
ContactMaterial default_ball_ball() {
  return {.stiffness = 5.0e8, .damping = 20.0, .friction = 0.00995 + 0.108, .friction_law = FrictionLaw::SpeedDependent,
          .friction_fast_ratio = 0.00995 / (0.00995 + 0.108), .friction_decay = 1.088};
}

// Under a cushion's push (hundreds of newtons) the thin cloth is squeezed flat and the ball bears on slate: the bed is
// as stiff as a phenolic ball on rigid slate, (4/3) E* sqrt(R) = 1.4e9 N/m^1.5 (docs/model.md#table). Damping 711 N s/m
// gives zeta = 0.45 at 1 m/s for a 0.17 kg ball, restitution 0.5 (measured ball-table value).
// Sliding friction 0.2, rolling resistance 0.01 (deceleration 0.098 m/s^2), spin friction 0.0117
// (angular deceleration 10 rad/s^2 for a pool ball at rest): all mid-range measured values.
ContactMaterial default_ball_cloth() {
  return {.stiffness = 1.4e9, .damping = 711.0, .friction = 0.2, .rolling_resistance = 0.01, .spin_friction = 0.0117};
}

// Rubber cushion, far softer than the balls: C_s = 3e7 N/m^1.5 (a contact of 1.6 ms at 1.5 m/s), damping 45.3 N s/m
// gives zeta = 0.134 at 1 m/s, restitution 0.8 (measured 0.6-0.9); cushion friction 0.2.
ContactMaterial default_ball_cushion() { return {.stiffness = 3.0e7, .damping = 45.3, .friction = 0.2}; }

// The back of a pocket (the rail's body lined with leather or rubber, docs/model.md#pockets): as soft as a cushion, far
// deader. No measured value is known. Hunt-Crossley damping, 3.087 s/m: restitution 0.3 at 1 m/s for a 0.17 kg ball,
// falling with speed (0.11 at 3, 0.03 at 10 m/s), so that a ball slammed into a pocket stays down as players expect.
ContactMaterial default_ball_pocket() {
  return {.stiffness = 3.0e7, .damping = 3.0870819808107512, .damping_law = DampingLaw::HuntCrossley, .friction = 0.2};
}

}  // namespace shotlab
