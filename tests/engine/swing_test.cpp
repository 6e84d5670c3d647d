// The swing's closed form (engine/swing.hpp): against the exact plane pendulum's period and speeds, and where it
// must not be used.
#include <cmath>

#include "engine/contacts.hpp"
#include "engine/swing.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

// A ball on a rod of length L from `anchor`, released from rest `amp` radians from the vertical in the vertical plane
// at `heading` radians about the vertical from +x; `model` fields as given.
nlohmann::json pendulum(double L, double amp, double heading, const nlohmann::json& model = nlohmann::json::object()) {
  const double h = L * std::sin(amp);
  nlohmann::json doc = {
      {"balls", {{{"id", "bob"}, {"position", {h * std::cos(heading), 1 - L * std::cos(amp), h * std::sin(heading)}}}}},
      {"rods", {{{"ball", "bob"}, {"anchor", {0, 1, 0}}}}},
      {"integrator", {{"abs_tol", 1e-10}, {"rel_tol", 1e-10}, {"max_steps_per_call", 1000000}}}};
  doc["model"] = model;
  return doc;
}

TEST(Swing, FollowsTheExactPendulumInAnyVerticalPlane) {
  // 75 degrees, in a plane turned 35 degrees about the vertical. The exact pendulum: period 4 K(k) / w0 with
  // k = sin(amp / 2), speed sqrt(2 g L (1 - cos amp)) at the bottom, a quarter period after the release.
  const double L = 0.5, amp = 75 * M_PI / 180, heading = 35 * M_PI / 180;
  const double k = std::sin(amp / 2), w0 = std::sqrt(kG / L), period = 4 * std::comp_ellint_1(k) / w0;
  auto fast = simulate(scene(pendulum(L, amp, heading)));
  auto plain = simulate(scene(pendulum(L, amp, heading, {{"swing_regime", false}})));
  const Vec3 start = position(fast->state().x, 0);
  advance_to(*fast, period / 4);
  EXPECT_NEAR(glm::length(velocity(fast->state().x, 0)), std::sqrt(2 * kG * L * (1 - std::cos(amp))), 1e-12);
  EXPECT_NEAR(position(fast->state().x, 0).y, 1 - L, 1e-12);
  advance_to(*fast, 3 * period);
  EXPECT_LT(glm::length(position(fast->state().x, 0) - start), 1e-11) << "three periods bring it back";
  EXPECT_LT(glm::length(velocity(fast->state().x, 0)), 1e-11);
  // The integrated pendulum agrees to its tolerance, at several times the right-hand sides.
  advance_to(*plain, 3 * period);
  EXPECT_LT(glm::length(position(plain->state().x, 0) - start), 1e-8);
  std::printf("[ swing    ] 3 periods of 75 degrees: %ld steps, %ld right-hand sides in closed form; %ld, %ld "
              "integrated\n",
              fast->stats().steps, fast->stats().rhs_evaluations, plain->stats().steps, plain->stats().rhs_evaluations);
  EXPECT_LT(3 * fast->stats().rhs_evaluations, plain->stats().rhs_evaluations);
}

TEST(Swing, OnlyWhereThePendulumsClosedFormHolds) {
  auto swing = [](const nlohmann::json& doc, auto&& change) {
    Prepared p = prepare(scene(doc));
    change(p.state.x);
    const ModelIndex index(p.model);
    return swing_of(p.model, p.state, index, p.state.x.data(), 0);
  };
  auto as_is = [](StateVector&) {};
  const double L = 0.2, amp = 0.5;
  const auto s = swing(pendulum(L, amp, 0.3), as_is);
  ASSERT_TRUE(s);
  EXPECT_NEAR(s->modulus, std::sin(amp / 2), 1e-15);
  // Its start is the state it was made from.
  Prepared p = prepare(scene(pendulum(L, amp, 0.3)));
  StateVector b(kBallDofs, 0.0);
  s->apply(0.0, b.data());
  EXPECT_LT(glm::length(position(b, 0) - position(p.state.x, 0)), 1e-15);
  EXPECT_LT(glm::length(velocity(b, 0)), 1e-15);
  // Taken up again from any point of the swing (each quarter of the phase, either side of the vertical, either way
  // round), it goes on as it was.
  const double period = 4 * std::comp_ellint_1(s->modulus) / s->omega;
  for (double t = period / 8; t < period; t += period / 4) {
    StateVector at(kBallDofs, 0.0), later(kBallDofs, 0.0), again(kBallDofs, 0.0);
    s->apply(t, at.data());
    const auto resumed =
        swing(pendulum(L, amp, 0.3), [&](StateVector& x) { std::copy_n(at.begin(), kBallDofs, x.begin()); });
    ASSERT_TRUE(resumed) << t;
    s->apply(t + 0.1, later.data());
    resumed->apply(0.1, again.data());
    EXPECT_LT(glm::length(position(again, 0) - position(later, 0)), 1e-14) << t;
    EXPECT_LT(glm::length(velocity(again, 0) - velocity(later, 0)), 1e-13) << t;
  }
  // Hanging straight down and pushed sideways: the plane is the push's.
  EXPECT_TRUE(swing(pendulum(L, 0, 0), [](StateVector& x) { set_velocity(x, 0, Vec3{0.3, 0, 0.4}); }));
  // Not: above the anchor's height, which free_acceleration's bound does not cover.
  EXPECT_FALSE(swing(pendulum(L, 1.7, 0), as_is));
  const double over = 2.1 * std::sqrt(kG * L);  // m/s at the bottom: swings past the anchor's height (2 sqrt(g L))
  EXPECT_FALSE(swing(pendulum(L, 0, 0), [&](StateVector& x) { set_velocity(x, 0, Vec3{over, 0, 0}); }));
  // Not: moving out of the plane through the rod (a spherical pendulum), off the rod's length, or along the rod.
  EXPECT_FALSE(swing(pendulum(L, amp, 0), [](StateVector& x) { set_velocity(x, 0, Vec3{0, 0, 1e-6}); }));
  EXPECT_FALSE(swing(pendulum(L, amp, 0), [](StateVector& x) { set_position(x, 0, position(x, 0) * 1.0000001); }));
  EXPECT_FALSE(swing(pendulum(L, 0, 0), [](StateVector& x) { set_velocity(x, 0, Vec3{0, 1e-6, 0}); }));
  // Not: asked not to, or touching another ball.
  EXPECT_FALSE(swing(pendulum(L, amp, 0, {{"swing_regime", false}}), as_is));
  nlohmann::json two = pendulum(L, 0, 0);
  two["balls"].push_back({{"id", "other"}, {"position", {2 * kR + 5e-7, 1 - L, 0}}});
  EXPECT_FALSE(swing(two, as_is));
  two["balls"][1]["position"] = {2 * kR + 1e-3, 1 - L, 0};
  EXPECT_TRUE(swing(two, as_is));
}

}  // namespace
}  // namespace shotlab::test
