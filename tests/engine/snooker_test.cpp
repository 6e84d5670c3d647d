// The snooker table and rack: the WPBSA's playing area and spots (baulk line 737 mm from the bottom cushion, the D's
// radius 292 mm, black 324 mm from the top cushion, pink midway between the blue and the top cushion), 15 reds packed
// behind the pink without touching it.
#include <cmath>

#include "support.hpp"

namespace shotlab::test {
namespace {

const InitialBall* find(const Scene& s, const std::string& id) {
  for (const InitialBall& b : s.balls)
    if (b.spec.id == id) return &b;
  return nullptr;
}

TEST(Snooker, TableAndRackFollowTheRules) {
  const Scene s = scene({{"table", {{"type", "snooker"}}}, {"ball_kind", "snooker"}, {"rack", {{"type", "snooker"}}}});
  ASSERT_TRUE(s.table);
  EXPECT_DOUBLE_EQ(s.table->length, 3.569);
  EXPECT_DOUBLE_EQ(s.table->width, 1.778);
  ASSERT_EQ(s.balls.size(), 21u);
  const double half = 3.569 / 2, r = 0.02625;
  const std::pair<const char*, Vec3> spots[] = {{"brown", {-half + 0.737, r, 0}},   {"yellow", {-half + 0.737, r, 0.292}},
                                                {"green", {-half + 0.737, r, -0.292}}, {"blue", {0, r, 0}},
                                                {"pink", {half / 2, r, 0}},           {"black", {half - 0.324, r, 0}}};
  for (const auto& [id, p] : spots) {
    const InitialBall* b = find(s, id);
    ASSERT_TRUE(b) << id;
    EXPECT_LT(glm::length(b->position - p), 1e-12) << id;
  }
  int reds = 0;
  double nearest = 1;
  for (const InitialBall& b : s.balls) {
    if (b.spec.id.rfind("red", 0) != 0) continue;
    ++reds;
    EXPECT_GT(b.position.x, half / 2) << b.spec.id << " behind the pink";
    nearest = std::min(nearest, glm::length(b.position - find(s, "pink")->position) - 2 * r);
  }
  EXPECT_EQ(reds, 15);
  EXPECT_GT(nearest, 0.0);  // the apex red does not touch the pink ...
  EXPECT_LT(nearest, 0.002);  // ... but is as close as a hand places it
  EXPECT_EQ(prepare(s).model.pockets.size(), 6u);
}

// A saved snooker scene writes its rack back and reads in as the same balls.
TEST(Snooker, RackRoundTrips) {
  const Scene s = scene({{"table", {{"type", "snooker"}}}, {"ball_kind", "snooker"}, {"rack", {{"type", "snooker"}}}});
  const Scene back = scene(scene_to_json(s));
  ASSERT_EQ(back.balls.size(), s.balls.size());
  for (size_t k = 0; k < s.balls.size(); ++k) EXPECT_EQ(back.balls[k].position, s.balls[k].position);
  EXPECT_EQ(scene_to_json(s)["rack"]["type"], "snooker");
}

}  // namespace
}  // namespace shotlab::test
