// The fast path's regimes (engine/regimes.cpp) against the full model they stand in for: a ball that rolls to rest
// in the closed-form rolling regime, has the decay tails of its speed and spin cut and then sleeps must end where the
// full model (every ball integrated with smoothed cloth friction, no sleeping) brings it.
#include <cstdio>

#include "support.hpp"

namespace shotlab::test {
namespace {

struct Rolled {
  Vec3 p, v, w;
  long steps;
  bool asleep;
};

Rolled roll_to(const nlohmann::json& doc, bool fast, double until) {
  nlohmann::json d = doc;
  if (!fast) d["model"] = {{"rolling_regime", false}, {"sleep_time", 0}};
  auto sim = simulate(scene(d));
  advance_to(*sim, until);
  const State& s = sim->state();
  return {position(s.x, 0), velocity(s.x, 0), spin(s.x, 0), sim->stats().steps, s.sleeping(0)};
}

// Rolling at 0.6 m/s with 15 rad/s of spin about the vertical: on the cloth (mu_r = 0.01) it rolls 1.8 m in 6.1 s;
// the vertical spin dies in 0.6 s. At 8 s the full model has decayed both tails to below 1e-12.
TEST(Regimes, BallRolledToRestStopsWhereTheFullModelStops) {
  const double v0 = 0.6;
  const nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {v0, 0, 0}},
                                           {"angular_velocity", {0, 15.0, -v0 / kR}}}});
  const Rolled fast = roll_to(doc, true, 8.0), full = roll_to(doc, false, 8.0);
  const double dp = glm::length(fast.p - full.p);
  std::printf("[ rest     ] rolled %.6f m; fast path %ld steps, full model %ld; |dp| = %.2e m, full |v| = %.1e m/s, "
              "R |w| = %.1e m/s\n",
              full.p.x, fast.steps, full.steps, dp, glm::length(full.v), kR * glm::length(full.w));
  EXPECT_GT(full.p.x, 1.0);  // it did roll
  EXPECT_LT(dp, 3e-8);  // 1e-8 m measured; cutting the speed at 1e-7 m/s moves the ball by under 1 nm
  // The fast path's ball is exactly at rest and asleep; the full model's tails are negligible by now.
  EXPECT_EQ(fast.v, Vec3(0.0));
  EXPECT_EQ(fast.w, Vec3(0.0));
  EXPECT_TRUE(fast.asleep);
  EXPECT_LT(glm::length(full.v) + kR * glm::length(full.w), 1e-9);
  EXPECT_LT(fast.steps * 5, full.steps);
}

}  // namespace
}  // namespace shotlab::test
