// The contact law's forms and the error control's units: the bed's component form (UpNormal) against the generic
// law, what counts as a friction switch (friction_switched), and a spin held to the tolerance as a surface speed
// (BallErrorChecker).
#include <random>

#include "engine/contact_force.hpp"
#include "engine/stepper.hpp"

#include "support.hpp"

namespace shotlab::test {
namespace {

// The bed's component form must be the same law: for random states of a ball on the cloth, sliding, rolling, spinning
// or nearly at rest (inside every band), the same forces to the last bit (a zero's sign aside, which == ignores).
TEST(ContactLaw, BedComponentFormIsTheGenericLaw) {
  const ContactMaterial cloth = empty_model().material(kBallCloth);
  const Smoothing smoothing{1000.0, 2e5};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> speed(-2.0, 2.0), slow(-2e-3, 2e-3), depth(1e-7, 2e-4);
  for (int n = 0; n < 2000; ++n) {
    auto draw = [&] { return n % 2 ? speed(rng) : slow(rng); };
    const Vec3 v{draw(), draw(), draw()}, w{draw() / kR, draw() / kR, draw() / kR};
    const double d = depth(rng), inv_m = 1 / kM, inv_i = kR * kR / (0.4 * kM * kR * kR);
    const Kinematics<Vec3> generic{kUp, d, v, v + kR * glm::cross(kUp, w), glm::dot(w, kUp), kR, inv_m + inv_i, inv_m, inv_i};
    const Kinematics<UpNormal> up{UpNormal{}, d, v, v + kR * normal_cross(UpNormal{}, w), normal_component(w, UpNormal{}),
                                  kR, inv_m + inv_i, inv_m, inv_i};
    for (bool clamp : {true, false}) {
      const ContactForce a = contact_force(cloth, generic, smoothing, clamp), b = contact_force(cloth, up, smoothing, clamp);
      ASSERT_EQ(a.normal, b.normal);
      ASSERT_EQ(a.force, b.force) << n;
      ASSERT_EQ(a.friction, b.friction) << n;
      ASSERT_EQ(a.rolling, b.rolling) << n;
      ASSERT_EQ(a.spin_torque, b.spin_torque) << n;
      ASSERT_EQ(a.bands, b.bands) << n;
    }
    ASSERT_EQ(generic.slip, up.slip);
    ASSERT_EQ(generic.spin_rel, up.spin_rel);
  }
}

// A switch is a term entering or leaving its band, or a saturated term turned around; inside the band a term runs
// smoothly through zero (a resting contact's round-off turns it every which way), and a stronger or weaker force in
// the same law is no switch.
TEST(ContactLaw, FrictionSwitches) {
  ContactForce sliding;
  sliding.friction = {-0.3, 0.0, 0.0};
  ContactForce reversed = sliding, stronger = sliding, in_band = sliding;
  reversed.friction = {0.3, 0.0, 0.0};
  stronger.friction = {-0.5, 0.0, 0.1};
  in_band.friction = {-0.1, 0.0, 0.0};
  in_band.bands = kSlipInBand;
  EXPECT_TRUE(friction_switched(FrictionLaw(sliding), FrictionLaw(reversed)));
  EXPECT_TRUE(friction_switched(FrictionLaw(sliding), FrictionLaw(in_band)));
  EXPECT_FALSE(friction_switched(FrictionLaw(sliding), FrictionLaw(stronger)));
  ContactForce in_band_turned = in_band;
  in_band_turned.friction = {1e-17, 0.0, 0.0};
  EXPECT_FALSE(friction_switched(FrictionLaw(in_band), FrictionLaw(in_band_turned)));
  ContactForce limited = in_band;
  limited.bands = kSlipInBand | kSlipLimited;
  EXPECT_TRUE(friction_switched(FrictionLaw(in_band), FrictionLaw(limited)));  // the rate limit set in: a kink in N
  ContactForce spin_a, spin_b;
  spin_a.spin_torque = 1e-4, spin_b.spin_torque = -1e-4;
  EXPECT_TRUE(friction_switched(FrictionLaw(spin_a), FrictionLaw(spin_b)));
}

// abs_tol holds a position in m, a velocity in m/s and a spin w as the surface speed R w in m/s: on a ball of radius
// 0.03 m an error of 1e-7 / 0.03 rad/s is one tolerance, as is 1e-7 m/s of velocity; the relative share counts the
// component's size and its change over the step, as odeint's default checker does.
TEST(ErrorControl, SpinIsHeldAsASurfaceSpeed) {
  const BallErrorChecker check(1e-7, 1e-7, {0.03});
  const StateVector at_rest(kBallDofs, 0.0);
  auto ratio = [&](int component, double error, const StateVector& x = StateVector(kBallDofs, 0.0)) {
    StateVector err(kBallDofs, 0.0);
    err[component] = error;
    return check.error(x, at_rest, err, 1e-3);
  };
  EXPECT_NEAR(ratio(0, 1e-7), 1.0, 1e-12);         // position, m
  EXPECT_NEAR(ratio(4, 1e-7), 1.0, 1e-12);         // velocity, m/s
  EXPECT_NEAR(ratio(7, 1e-7 / 0.03), 1.0, 1e-12);  // spin, rad/s: R w = 1e-7 m/s
  EXPECT_NEAR(ratio(7, 1e-7), 0.03, 1e-12);
  StateVector spinning(kBallDofs, 0.0);
  spinning[7] = 100.0;  // rad/s: a relative share of 1e-7 x 100 rad/s besides the absolute 1e-7 / 0.03
  EXPECT_NEAR(ratio(7, 1e-5, spinning), 1e-5 / (1e-7 / 0.03 + 1e-5), 1e-12);
}

}  // namespace
}  // namespace shotlab::test
