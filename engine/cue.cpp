#include "shotlab/cue.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "message.hpp"
#include "shotlab/scene.hpp"

namespace shotlab {

Vec3 aim_direction(double aim) { return {std::cos(aim), 0.0, -std::sin(aim)}; }

StrikeResult strike(const CueStrike& cue, double mass, double radius) {
  const double offset2 = cue.side * cue.side + cue.height * cue.height;
  if (offset2 >= 1.0) throw std::invalid_argument("cue tip offset must be inside the ball (side^2 + height^2 < 1)");
  const Vec3 h = aim_direction(cue.aim);
  const Vec3 s = glm::cross(h, kUp);  // shooter's right
  const Vec3 q = radius * (cue.side * s + cue.height * kUp - std::sqrt(1.0 - offset2) * h);
  const Vec3 d = std::cos(cue.elevation) * h - std::sin(cue.elevation) * kUp;
  const double inertia = 0.4 * mass * radius * radius;
  const Vec3 qxd = glm::cross(q, d);
  const double j = (1.0 + cue.tip_restitution) * cue.speed / (1.0 / mass + 1.0 / cue.cue_mass + glm::dot(qxd, qxd) / inertia);
  // Squirt turns the velocity about the vertical, to the left for right side (counter-clockwise from above: +).
  const double turn = cue.end_mass > 0 ? std::copysign(squirt_angle(cue.side, mass / cue.end_mass), cue.side) : 0.0;
  const Vec3 v = j / mass * d;
  const Vec3 turned{std::cos(turn) * v.x + std::sin(turn) * v.z, v.y, -std::sin(turn) * v.x + std::cos(turn) * v.z};
  return {turned, j / inertia * qxd, j, turn, std::sqrt(offset2) > cue.miscue_limit};
}

std::string cue_problem(const CueStrike& cue) {
  const auto number = message_number;
  for (const auto& [name, v] : {std::pair{"speed", cue.speed}, {"aim", cue.aim}, {"side", cue.side},
                                {"height", cue.height}, {"elevation", cue.elevation}})
    if (!std::isfinite(v)) return std::string(name) + ": not finite";
  if (!(cue.speed > 0)) return "speed: must be above 0 m/s";
  if (cue.speed > kMaxStartSpeed)
    return "speed: " + number(cue.speed) + " m/s is faster than a cue strikes (at most " + number(kMaxStartSpeed) +
           " m/s; a hard break is 10-14 m/s)";
  if (cue.elevation < 0 || cue.elevation > kMaxElevation)
    return "elevation: must be 0 to 90 degrees (a level to a vertical cue)";
  if (cue.side * cue.side + cue.height * cue.height >= 1)
    return "side, height: the tip offset must lie inside the ball";
  return "";
}

// The tip does not slip on the ball while the shaft's end (mass m_e) is pushed sideways: the ball's sideways
// momentum is the end's, opposite, and the contact point's sideways speed, v_y + (5/2) c (c v_y + s v_x), is the
// end's, which gives the ratio v_y / v_x (docs/model.md#cue).
double squirt_angle(double side, double mass_ratio) {
  const double s = std::abs(side), c = std::sqrt(std::max(0.0, 1 - s * s));
  return std::atan(2.5 * s * c / (1 + mass_ratio + 2.5 * c * c));
}

}  // namespace shotlab
