// The cushion's contact height: a table's nose_height is where a resting ball touches the cushion (the WPA's
// specification is 62.5-64.5 % of the ball's diameter), on the nose line that length and width are measured between.
#include <cmath>

#include "support.hpp"

namespace shotlab::test {
namespace {

// A resting ball of radius r whose surface reaches a cushion at height h on the nose line has its centre
// sqrt(r^2 - (h - r)^2) from that line (the geometry of a circle touching a point). Placed so, it touches there.
TEST(Cushion, ARestingBallTouchesAtTheNoseHeight) {
  struct Case {
    const char* table;
    const char* ball_kind;
    double half_width, radius, nose;  // m
  };
  for (const Case& c : {Case{"pool", "pool", 1.27 / 2, 0.028575, 0.0365}, Case{"carom", "carom", 1.42 / 2, 0.03075, 0.635 * 0.0615}}) {
    const double reach = std::sqrt(c.radius * c.radius - (c.nose - c.radius) * (c.nose - c.radius));
    const nlohmann::json doc = {{"table", {{"type", c.table}}}, {"ball_kind", c.ball_kind},
                                {"balls", {{{"id", "a"}, {"position", {0.6, c.radius, c.half_width - reach + 5e-6}}}}}};
    const auto sim = simulate(scene(doc));
    bool found = false;
    for (const Contact& k : sim->contacts()) {
      if (k.collider < 0 || k.normal.y > 0.5) continue;  // the bed
      found = true;
      // Within 10 um: the resting ball sinks 6.5-7.5 um into the cloth, and is pushed 5 um into the cushion.
      EXPECT_NEAR(k.point.y, c.nose, 1e-5) << c.table;
      EXPECT_NEAR(k.point.z, c.half_width, 1e-5) << c.table;
      const double share = k.point.y / (2 * c.radius);
      EXPECT_TRUE(share > 0.625 && share < 0.645) << c.table << ": " << share;
    }
    EXPECT_TRUE(found) << c.table << ": the ball touches the cushion";
  }
}

// Mathavan, Jackson and Parkin (2010, Proc. IMechE C 224:1863): a stun snooker ball into a cushion with restitution
// 0.98 and friction 0.14, cloth friction 0.212, contact 7R/5 above the bed. Their model's rebound (speed ratio, angle
// from the cushion line) at 15, 45 and 90 degrees incidence: 0.878 / 16.4, 0.756 / 56.2, 0.837 / 90. Here with the
// default cloth and cushion stiffness, the ball leaving the cushion within 0.03 and 2 degrees of theirs.
TEST(Cushion, StunReboundsFollowMathavan) {
  const double r = 0.02625, v = 1.5, sin_t = 0.4;  // sin of the contact's tilt at 7R/5
  const double z_touch = -0.71 + r * std::sqrt(1 - sin_t * sin_t) + 30e-6;  // 30 um short of the carom back cushion
  struct Case {
    double incidence, ratio, angle;  // degrees from the cushion line
  };
  for (const Case& c : {Case{15, 0.878, 16.4}, Case{45, 0.756, 56.2}, Case{90, 0.837, 90.0}}) {
    const double a = c.incidence * M_PI / 180;
    const nlohmann::json doc = {
        {"ball_kind", "snooker"},
        {"table", {{"type", "carom"}, {"nose_height", 1.4 * r}, {"ball_radius", r}}},
        {"materials", {{"ball_cushion", {{"restitution", 0.98}, {"restitution_speed", v * std::sin(a)}, {"friction", 0.14}}},
                       {"ball_cloth", {{"friction", 0.212}}}}},
        {"balls", {{{"id", "cue"}, {"position", {0, r, z_touch}}, {"velocity", {v * std::cos(a), 0, -v * std::sin(a)}}}}}};
    auto sim = simulate(scene(doc));
    run_until(*sim, 0.05, [&] { return event_time(*sim, "contact_end", "cue", "cushion-back") >= 0; }, 1e-4);
    const double left = event_time(*sim, "contact_end", "cue", "cushion-back");
    ASSERT_GT(left, 0) << c.incidence;
    auto again = simulate(scene(doc));
    ASSERT_EQ(again->advance(left), Status::Ok);
    const Vec3 u = velocity(again->state().x, 0);
    EXPECT_NEAR(std::hypot(u.x, u.z) / v, c.ratio, 0.03) << c.incidence;
    EXPECT_NEAR(std::atan2(u.z, u.x) * 180 / M_PI, c.angle, 2.0) << c.incidence;
    std::printf("incidence %g: ratio %.3f (Mathavan %.3f), angle %.2f (%.1f)\n", c.incidence,
                std::hypot(u.x, u.z) / v, c.ratio, std::atan2(u.z, u.x) * 180 / M_PI, c.angle);
  }
}

}  // namespace
}  // namespace shotlab::test
