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

}  // namespace
}  // namespace shotlab::test
