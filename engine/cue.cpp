#include "shotlab/cue.hpp"

#include <stdexcept>

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
  return {j / mass * d, j / inertia * qxd, j, std::sqrt(offset2) > cue.miscue_limit};
}

}  // namespace shotlab
