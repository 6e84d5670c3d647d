// Throw: a stun cut shot sends the object ball off the line of centres by the friction between the balls. The
// expected angles come from the rigid impulse model of Alciatore's technical proof TP A-14 (equal solid balls, one
// impulse, the slip between the surfaces changed by 7/m per unit of tangential impulse), with the friction coefficient
// mu(u) = a + b exp(-c u) of TP A-28 (a = 0.00995, b = 0.108, c = 1.088 s/m) taken at the slip u of the moment, as the
// engine's force law does: while the contact slides, du/dP = -7 mu(u) / m over the normal impulse P, which integrates
// in closed form. docs/model.md#friction-speed.
#include <cmath>

#include "support.hpp"

namespace shotlab::test {
namespace {

constexpr double kA = 0.00995, kB = 0.108, kC = 1.088;  // TP A-28's fit
constexpr double kCut = 30.0 * M_PI / 180;              // half-ball hit

// Degrees: the throw by the impulse model for a stun ball at v (m/s) whose normal impulse per unit mass is p_n (m/s).
double expected_throw(double v, double p_n) {
  const double u0 = v * std::sin(kCut);
  // The normal impulse (per unit mass) at which the slip would reach zero: then the surfaces roll on each other.
  const double to_stick = std::log((kA * std::exp(kC * u0) + kB) / (kA + kB)) / (kA * kC) / 7;
  double u_end = 0;
  if (to_stick > p_n) u_end = std::log(((kA * std::exp(kC * u0) + kB) * std::exp(-7 * kA * kC * p_n) - kB) / kA) / kC;
  return std::atan((u0 - u_end) / (7 * p_n)) * 180 / M_PI;
}

struct Departure {
  double angle;   // degrees, the object ball's direction from the line of centres at first contact, towards the throw
  double normal;  // m/s, its speed along that line
};

// The object ball's departure after a stun half-ball hit at v in free space, with the ball-ball material `material`.
Departure departure(double v, const nlohmann::json& material) {
  const double c = std::cos(kCut), s = std::sin(kCut);
  nlohmann::json doc = {
      {"gravity", {0, 0, 0}},
      {"integrator", {{"method", "dopri5"}, {"abs_tol", 1e-10}, {"rel_tol", 1e-10}, {"max_steps_per_call", 1000000}}},
      {"balls",
       {{{"id", "cue"}, {"position", {-2 * kR * c - 1e-4, 0, 2 * kR * s}}, {"velocity", {v, 0, 0}}},
        {{"id", "object"}, {"position", {0, 0, 0}}}}}};
  doc["materials"]["ball_ball"] = material;
  auto sim = simulate(scene(doc));
  advance_to(*sim, 0.003);  // the contact lasts under 0.5 ms
  const Vec3 u = velocity(sim->state().x, 1);
  const Vec3 along{c, 0, -s}, across{s, 0, c};  // the line of centres at contact, and the cue ball's side of it
  return {std::atan2(glm::dot(u, across), glm::dot(u, along)) * 180 / M_PI, glm::dot(u, along)};
}

// Measured against the same shot without friction: a soft contact turns the line of centres while the balls overlap,
// which sends even a frictionless object ball 0.05-0.26 degrees off the line at first contact.
TEST(Throw, StunHalfBallHitFollowsTheSpeedDependentFit) {
  for (const double damping : {0.0, 20.0}) {
    for (const double v : {0.447, 1.341, 3.129}) {
      nlohmann::json material = {{"damping", damping}};  // the default law: the fit, as friction and fast ratio
      const Departure with = departure(v, material);
      material["friction"] = 0;
      const Departure without = departure(v, material);
      const double expected = expected_throw(v, without.normal);
      EXPECT_NEAR(with.angle - without.angle, expected, 0.1) << "v " << v << " m/s, damping " << damping;
      std::printf("throw at %.3f m/s, damping %g: %.3f deg (impulse model %.3f)\n", v, damping,
                  with.angle - without.angle, expected);
    }
  }
}

// A constant coefficient stays selectable: then the throw is atan(mu) while the contact slides (TP A-14).
TEST(Throw, ConstantCoefficientThrowsByItsArctangent) {
  const double v = 3.129, mu = 0.05;  // slides throughout: mu < tan(30 deg) / 7
  const nlohmann::json material = {{"damping", 0}, {"friction_law", "constant"}, {"friction", mu}};
  const Departure with = departure(v, material);
  const Departure without = departure(v, {{"damping", 0}, {"friction", 0}});
  EXPECT_NEAR(with.angle - without.angle, std::atan(mu) * 180 / M_PI, 0.1);
}

}  // namespace
}  // namespace shotlab::test
