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

}  // namespace
}  // namespace shotlab::test
