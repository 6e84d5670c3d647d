// The flight (Options::flight_regime, regimes.hpp): a ball touching nothing moves in closed form under gravity, against
// the projectile's textbook motion, and only while it touches nothing.
#include <cmath>

#include "engine/contacts.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

// A ball thrown from (0, y0, 0) at velocity v with spin w over the endless cloth.
nlohmann::json throw_scene(double y0, const Vec3& v, const Vec3& w, bool flight = true) {
  nlohmann::json doc = cloth_scene({{{"id", "b"}, {"position", {0, y0, 0}}, {"velocity", {v.x, v.y, v.z}},
                                     {"angular_velocity", {w.x, w.y, w.z}}}});
  doc["integrator"] = {{"abs_tol", 1e-9}, {"rel_tol", 1e-9}, {"max_steps_per_call", 1000000}};
  doc["model"] = {{"flight_regime", flight}};
  return doc;
}

TEST(Flight, FollowsTheProjectileAndTouchesDownWhereItsLowestPointReachesTheBed) {
  const double y0 = 0.3;
  const Vec3 v{1.2, 2.0, -0.5}, w{3, -4, 5};
  // y(t) = y0 + vy t - g t^2 / 2 reaches the radius at the larger root.
  const double land = (v.y + std::sqrt(v.y * v.y + 2 * kG * (y0 - kR))) / kG;
  auto fast = simulate(scene(throw_scene(y0, v, w)));
  auto plain = simulate(scene(throw_scene(y0, v, w, false)));
  const double t = land - 1e-3;
  advance_to(*fast, t);
  advance_to(*plain, t);
  const StateVector& x = fast->state().x;
  EXPECT_NEAR(position(x, 0).x, v.x * t, 1e-13);
  EXPECT_NEAR(position(x, 0).y, y0 + v.y * t - 0.5 * kG * t * t, 1e-13);
  EXPECT_NEAR(position(x, 0).z, v.z * t, 1e-13);
  EXPECT_NEAR(velocity(x, 0).y, v.y - kG * t, 1e-13);
  EXPECT_EQ(spin(x, 0), w) << "nothing acts on the spin in flight";
  // The integrated flight agrees to its tolerance, at many times the right-hand sides.
  EXPECT_LT(glm::length(position(plain->state().x, 0) - position(x, 0)), 1e-8);
  std::printf("[ flight   ] %.3f s in the air: %ld steps, %ld right-hand sides in closed form; %ld, %ld integrated\n", t,
              fast->stats().steps, fast->stats().rhs_evaluations, plain->stats().steps, plain->stats().rhs_evaluations);
  EXPECT_LT(3 * fast->stats().rhs_evaluations, plain->stats().rhs_evaluations);
  // The contact with the bed begins where the analytic path brings the ball's lowest point to it.
  advance_to(*fast, land + 1e-3);
  EXPECT_NEAR(event_time(*fast, "contact_begin", "b"), land, 1e-9);
}

TEST(Flight, OnlyForABallThatTouchesNothing) {
  Prepared p = prepare(scene(throw_scene(0.3, {0, 0, 0}, {0, 0, 0})));
  const ModelIndex index(p.model);
  auto clear_at = [&](double height) {
    p.state.x[1] = height;
    return clear_of_contacts(p.model, index, p.state, p.state.x.data(), 0);
  };
  const double margin = p.model.options.contact_margin;
  EXPECT_TRUE(clear_at(0.3));
  EXPECT_TRUE(clear_at(kR + 2 * margin));
  EXPECT_FALSE(clear_at(kR + 0.5 * margin)) << "within contact_margin of the bed";
  EXPECT_FALSE(clear_at(kR - 1e-5)) << "resting in the bed";
}

}  // namespace
}  // namespace shotlab::test
