// Contact materials: how a ball interacts with what it touches (another ball, the cloth, a cushion).
// One struct serves every pair; terms a pair does not use are zero and cost nothing.
#pragma once
#include <cmath>
#include <string>

namespace shotlab {

// How the normal force loses energy (docs/model.md#damping):
//  - Linear (thesis):  F = C_s d^m + C_d d'        restitution FALLS as impact speed falls (unlike real balls)
//  - HuntCrossley:     F = C_s d^m (1 + C_d d')   restitution falls as impact speed RISES (like real balls);
//                      C_d is then in s/m.
// In both, d' is the rate of penetration (> 0 while approaching) and F is clamped at F >= 0: the damping term would
// otherwise pull the bodies together as they separate, which no real contact does.
enum class DampingLaw { Linear, HuntCrossley };

// How the sliding friction coefficient depends on the slip speed u at the contact (docs/model.md#friction-speed):
//  - Constant:        mu = friction
//  - SpeedDependent:  mu(u) = friction (r + (1 - r) exp(-friction_decay u)), r = friction_fast_ratio: the form of
//                     the ball-ball fit to Marlow's measurements, evaluated at the slip of the moment. `friction` stays
//                     the scale (0: frictionless). Ball-ball contacts only: the bed's closed forms assume a constant.
enum class FrictionLaw { Constant, SpeedDependent };

struct ContactMaterial {
  double stiffness = 0;           // C_s, N/m^exponent (Hertz: N/m^1.5)
  double damping = 0;             // C_d, N s/m (Linear) or s/m (HuntCrossley)
  double exponent = 1.5;          // m of F = C_s d^m; 1.5 is Hertz
  DampingLaw damping_law = DampingLaw::Linear;
  double friction = 0;            // Coulomb sliding friction coefficient at the contact point (dimensionless);
                                  // with FrictionLaw::SpeedDependent, its value at zero slip
  FrictionLaw friction_law = FrictionLaw::Constant;
  double friction_fast_ratio = 1;  // SpeedDependent: the coefficient at high slip speed over `friction`, 0 to 1
  double friction_decay = 0;       // SpeedDependent: s/m, how fast the coefficient falls towards its fast value
  double rolling_resistance = 0;  // mu_r: resistance force mu_r |F_n| against rolling (dimensionless; on a flat
                                  // table the deceleration is mu_r g, docs/model.md#rolling-resistance)
  double spin_friction = 0;       // mu_sp: torque mu_sp R |F_n| against spin about the contact normal (dimensionless;
                                  // angular deceleration 5 mu_sp g / (2 R) for a ball resting on the table)

  // Restitution as a setting (restitution.hpp): when restitution > 0, the damping (and with contact_time > 0 the
  // stiffness) is derived at load so that a head-on impact at restitution_speed has this restitution and duration.
  double restitution = 0;         // e, 0 to 1; 0: the damping is as given
  double restitution_speed = 1;   // m/s, the impact speed e (and contact_time) refers to
  double contact_time = 0;        // s; 0: the stiffness is as given

  // The sliding friction coefficient at slip speed u (m/s).
  double friction_at(double u) const {
    if (friction_law == FrictionLaw::Constant) return friction;
    return friction * (friction_fast_ratio + (1 - friction_fast_ratio) * std::exp(-friction_decay * u));
  }
};

// Defaults from measured values (docs/model.md#parameters; docs/scene-format.md explains each number).
ContactMaterial default_ball_ball();
ContactMaterial default_ball_cloth();
ContactMaterial default_ball_cushion();
ContactMaterial default_ball_pocket();  // a pocket's back, which tables with pockets add (table.hpp)

}  // namespace shotlab
