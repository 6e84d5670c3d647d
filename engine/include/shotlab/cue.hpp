// Cue strike: from cue speed, aim, elevation and tip offset to the ball's initial velocity and spin.
//
// Model (the standard rigid-cue impulse model, as in pooltool and Dr. Dave Alciatore's technical proofs): the cue is
// a rigid body of mass M moving at V0 along its axis d; the tip hits the ball (mass m, radius R, I = 2/5 m R^2) at
// the surface point Q, with an impulse J along d and restitution e between tip and ball along d. Momentum:
// ball v = J d / m, w = (Q x d) J / I; cue V = V0 - J / M. Restitution of the normal approach at Q:
// (v + w x Q).d - V = e V0, and (w x Q).d = J |Q x d|^2 / I, so
//     J = (1 + e) V0 / (1/m + 1/M + |Q x d|^2 / I).
// Q is where the cue meets the ball: `side` (right, +) and `height` (up, +) are offsets in ball radii in the
// vertical plane across the aim line, Q = R (side s + height y - sqrt(1 - side^2 - height^2) h), with h the
// horizontal aim and s = h x y the shooter's right. The cue axis is tilted down by the elevation: d = cos(el) h -
// sin(el) y, so an elevated cue drives the ball into the cloth; the table contact then makes it bounce (jump shots)
// and swerve. Squirt (docs/model.md#cue): with side, the ball leaves off the cue's line, away from the tip's side, by
// the angle of Alciatore's TP A-31, set by the shaft's effective end mass.
#pragma once
#include <string>

#include "shotlab/vec.hpp"

namespace shotlab {

inline constexpr double kMaxElevation = 1.5707963267948966;  // rad: a vertical cue (a cue's elevation is 0 to this)

struct CueStrike {
  std::string ball;               // id of the struck ball
  double speed = 2.0;             // V0, m/s
  double aim = 0.0;               // heading in the table plane, rad: 0 = +x, pi/2 = -z (counter-clockwise from above)
  double elevation = 0.0;         // rad, 0 = level cue
  double side = 0.0;              // tip offset right of centre, ball radii
  double height = 0.0;            // tip offset above centre, ball radii (+ follow, - draw)
  double cue_mass = 0.54;         // M, kg (19 oz)
  double end_mass = 0.008;        // kg, the shaft's effective end mass that sets squirt (standard shaft); 0: none
  double tip_restitution = 0.75;  // e between tip and ball
  double miscue_limit = 0.5;      // tip offsets beyond this fraction of R miscue in practice
};

struct StrikeResult {
  Vec3 velocity;     // m/s
  Vec3 spin;         // rad/s
  double impulse;    // N s
  double squirt;     // rad: the heading's turn off the cue's line, + to the left (counter-clockwise from above)
  bool miscue;       // tip offset beyond miscue_limit: the result is reported, and a real cue would likely slip
};

// Horizontal unit aim direction of a heading angle (rad).
Vec3 aim_direction(double aim);

StrikeResult strike(const CueStrike& cue, double mass, double radius);

// What a cue strike may not be, naming the field ("speed: ..."), or "" when it may be struck: a speed above 0 and at
// most kMaxStartSpeed (scene.hpp), an elevation from 0 to kMaxElevation, a tip offset inside the ball, every number
// finite. The scene check and the C API's strike share it.
std::string cue_problem(const CueStrike& cue);

// rad: the squirt angle of TP A-31 for a tip offset `side` (ball radii) and ball mass over end mass, always >= 0:
// tan a = (5/2) s c / (1 + m / m_e + (5/2) c^2) with s = |side|, c = sqrt(1 - s^2).
double squirt_angle(double side, double mass_ratio);

}  // namespace shotlab
