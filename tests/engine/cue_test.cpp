// Cue strike: the rigid-cue impulse model against results derived independently of it.
#include <gtest/gtest.h>

#include "shotlab/cue.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

TEST(Cue, CentreHitIsATwoBodyCollision) {
  // A level centre hit is a 1-D collision of the cue (M) with the ball (m): v = (1 + e) M V0 / (M + m), no spin.
  CueStrike c;
  c.speed = 3.0;
  const StrikeResult s = strike(c, kM, kR);
  EXPECT_NEAR(s.velocity.x, (1 + c.tip_restitution) * c.cue_mass * c.speed / (c.cue_mass + kM), 1e-12);
  EXPECT_NEAR(glm::length(s.spin), 0.0, 1e-12);
  EXPECT_FALSE(s.miscue);
}

TEST(Cue, HitTwoFifthsAboveCentreRollsAtOnce) {
  // The classic result: a horizontal impulse at height 2R/5 above the centre gives R w = v, natural roll.
  CueStrike c;
  c.height = 0.4;
  const StrikeResult s = strike(c, kM, kR);
  EXPECT_NEAR(-s.spin.z * kR, s.velocity.x, 1e-12);  // rolling in +x has w_z = -v/R
}

TEST(Cue, DrawSideAndAim) {
  CueStrike c;
  c.aim = M_PI / 2;  // heading -z
  c.height = -0.5;
  c.side = 0.3;
  c.end_mass = 0;  // no squirt: the impulse along the cue (squirt has its own tests)
  const StrikeResult s = strike(c, kM, kR);
  EXPECT_NEAR(s.velocity.x, 0, 1e-12);
  EXPECT_LT(s.velocity.z, 0);
  // Draw for motion in -z: the slip v + R y x w points along the motion (backspin), so u_z < v_z.
  const Vec3 u = s.velocity + kR * glm::cross(Vec3{0, 1, 0}, s.spin);
  EXPECT_LT(u.z, s.velocity.z);
  // Right-hand side spin: the tip pushes the ball's right side forward, turning it counter-clockwise seen from
  // above (positive about +y), which is what makes it rebound to the right off a cushion.
  EXPECT_GT(s.spin.y, 0);
  EXPECT_TRUE(s.miscue);  // offset sqrt(0.34) = 0.58 R is past the half-radius limit
}

TEST(Cue, ElevatedCueDrivesTheBallIntoTheCloth) {
  CueStrike c;
  c.elevation = 30 * M_PI / 180;
  const StrikeResult s = strike(c, kM, kR);
  EXPECT_NEAR(s.velocity.y / s.velocity.x, -std::tan(c.elevation), 1e-12);
}

TEST(Cue, ElevatedShotJumps) {
  auto sim = simulate(load_scene(preset("jump.json")));
  ASSERT_EQ(sim->advance(1.0), Status::Ok);
  EXPECT_GE(event_time(*sim, "airborne", "cue"), 0.0);
}

// Squirt, Alciatore's TP A-31: the tip grips the ball while the shaft's end (mass m_e) is pushed sideways, so the ball
// leaves at tan a = (5/2) s sqrt(1 - s^2) / (1 + m / m_e + (5/2) (1 - s^2)) off the cue line (s: side offset in radii),
// away from the side the tip hits.
TEST(Cue, SquirtFollowsTheEndMassModel) {
  for (const double side : {0.1, 0.3, 0.5, 0.6}) {
    for (const double end_mass : {0.004, 0.008, 0.016}) {
      CueStrike c;
      c.side = side, c.end_mass = end_mass;
      const StrikeResult s = strike(c, kM, kR);
      const double k = 1 - side * side;
      const double expected = std::atan(2.5 * side * std::sqrt(k) / (1 + kM / end_mass + 2.5 * k));
      // Aim 0 heads +x; the shooter's right is +z; right side sends the ball left, to -z.
      EXPECT_NEAR(std::atan2(-s.velocity.z, s.velocity.x), expected, 1e-12) << side << " " << end_mass;
      EXPECT_NEAR(s.squirt, expected, 1e-12);
      c.side = -side;
      EXPECT_NEAR(strike(c, kM, kR).squirt, -expected, 1e-12);  // left side: to the right
    }
  }
  CueStrike none;
  none.side = 0.5, none.end_mass = 0;
  EXPECT_EQ(strike(none, kM, kR).squirt, 0.0);
  // A standard shaft (8 g) at half a radius of side: 2.6 degrees.
  EXPECT_NEAR(squirt_angle(0.5, kM / 0.008) * 180 / M_PI, 2.57, 0.01);
}

// On the table, a level cue with side sends the ball straight along the squirted line (spin about the vertical does
// not bend its path).
TEST(Cue, SquirtedBallRunsOnTheTurnedLine) {
  const nlohmann::json doc = {{"table", {{"type", "pool"}}},
                              {"balls", {{{"id", "cue"}, {"position", {-0.8, kR, 0}}}}},
                              {"cue", {{"ball", "cue"}, {"speed", 2.0}, {"side", 0.4}}}};
  auto sim = simulate(scene(doc));
  advance_to(*sim, 0.3);
  const Vec3 p = position(sim->state().x, 0);
  const double heading = std::atan2(-p.z, p.x + 0.8);
  EXPECT_NEAR(heading, squirt_angle(0.4, kM / CueStrike{}.end_mass), 1e-4);
}

// The squirt-and-swerve preset shows both: the ball leaves left of the cue line, then the elevated cue's swerve bends
// it back to the right of it.
TEST(Cue, SquirtThenSwervePreset) {
  auto sim = simulate(load_scene(preset("swerve.json")));
  double leftmost = 0;
  for (int k = 0; k < 24; ++k) {
    advance_to(*sim, 0.05 * (k + 1));
    leftmost = std::min(leftmost, position(sim->state().x, 0).z);  // aim +x: left is -z
  }
  EXPECT_LT(leftmost, -0.002);
  EXPECT_GT(position(sim->state().x, 0).z, 0.02);
}

}  // namespace
}  // namespace shotlab::test
