// Islands (engine/island.hpp, engine/partition.hpp): the fast path integrates groups of balls apart. What must hold:
// balls that can touch share an island, islands never miss a contact between them, and a shot split into islands
// ends where the single all-ball system ends.
#include <cstdio>

#include "engine/partition.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

// Every ball integrated, as one system, all along (the plain path but for the regimes on the bed, which these scenes
// without a bed do not use).
const std::vector<std::string> kEveryBallIntegrated = {"model.swing_regime=false", "model.flight_regime=false",
                                                       "model.sleep_time=0", "model.islands=false"};

nlohmann::json ball(const std::string& id, double x, double z, double vx = 0, double vz = 0) {
  return {{"id", id}, {"position", {x, kR, z}}, {"velocity", {vx, 0, vz}}, {"angular_velocity", {vz / kR, 0, -vx / kR}}};
}

std::vector<std::vector<int>> islands_of(const Simulation& sim) {
  std::vector<std::vector<int>> out;
  for (const auto& balls : sim.island_balls()) out.push_back(balls);
  return out;
}

// Two balls rolling apart on opposite halves of the cloth are two islands; a resting ball nothing can reach sleeps
// in none.
TEST(Islands, BallsFarApartIntegrateApart) {
  auto sim = simulate(scene(cloth_scene({ball("a", -0.5, 0, -1.0), ball("b", 0.5, 0, 1.0), ball("c", 0, 0.5)})));
  EXPECT_EQ(islands_of(*sim), (std::vector<std::vector<int>>{{0}, {1}}));
}

// A ball rolling at a resting pair: within the link time it shares an island with the ball it is about to hit and,
// through it, with the frozen neighbour that wakes with it.
TEST(Islands, BallAboutToHitJoinsTheSleepersItWakes) {
  const double gap = 1e-4;  // m, closed in 0.1 ms at 1 m/s
  auto sim = simulate(scene(cloth_scene({ball("cue", -2 * kR - gap, 0, 1.0), ball("b", 0, 0), ball("c", 2 * kR, 0)})));
  ASSERT_TRUE(sim->state().sleeping(1) && sim->state().sleeping(2));
  EXPECT_EQ(islands_of(*sim), (std::vector<std::vector<int>>{{0, 1, 2}}));
}

// A sleeper that two islands may both reach joins them into one: otherwise each would move it on its own.
TEST(Islands, SleeperTwoIslandsMayReachJoinsThem) {
  Prepared p = prepare(scene(cloth_scene({ball("left", -2 * kR - 2e-4, 0, 1.0), ball("mid", 0, 0),
                                          ball("right", 2 * kR + 2e-4, 0, -1.0)})));
  p.state.asleep = {0, 1, 0};
  const ModelIndex index(p.model);
  const Partition part = Partitioner(p.model, index)(p.state, {0, 2});
  EXPECT_EQ(part.islands, (std::vector<std::vector<int>>{{0, 1, 2}}));
  // Farther apart instead: two islands, each with a horizon before which it cannot reach the sleeper (gap / its
  // speed bound, over the 1 m/s it moves at); the right one starts nearer.
  set_position(p.state.x, 0, Vec3(-2 * kR - 0.015, kR, 0));
  set_position(p.state.x, 2, Vec3(2 * kR + 0.01, kR, 0));
  const Partition apart = Partitioner(p.model, index)(p.state, {0, 2});
  EXPECT_EQ(apart.islands, (std::vector<std::vector<int>>{{0}, {2}}));
  ASSERT_EQ(apart.horizon.size(), 2u);
  EXPECT_GT(apart.horizon[1], 0.0);
  EXPECT_LE(apart.horizon[1], 0.01);
  EXPECT_GT(apart.horizon[0], apart.horizon[1]);
  EXPECT_LE(apart.horizon[0], 0.015);
}

// Each island runs to its own deadline: a ball rolling alone in one corner is not cut short by a collision at the
// other end of the table. It takes a handful of long steps (the closed-form rolling regime, looked at again at most
// every 250 ms), not one for every look at the colliding pair.
TEST(Islands, LoneBallIsNotCutShortByACollisionElsewhere) {
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"balls", {ball("lone", -1.0, 0.5, 0.3), ball("cue", 0.5, -0.3, 1.5), ball("obj", 0.9, -0.3)}}};
  auto sim = simulate(scene(doc));
  long lone_steps = 0, others = 0;
  sim->set_observer([&](const StepView& step) { (step.balls == std::vector<int>{0} ? lone_steps : others) += 1; });
  ASSERT_EQ(sim->advance(1.0), Status::Ok) << sim->diagnostic();
  std::printf("[ islands  ] lone ball: %ld steps in 1 s; the colliding pair: %ld\n", lone_steps, others);
  EXPECT_GT(others, 100);  // the collision and the slides around it
  EXPECT_LT(lone_steps, 40);
}

// Lone rolling balls follow known paths (FreePath, regimes.hpp), so islands look at each other when those paths may
// meet, not whenever their speed bounds could close the gap. Two balls rolling side by side 10 cm apart at 1 m/s
// could close their 4.3 cm gap in 18 ms at their speed bounds: 55 looks a second. A pair rolling at each other
// along lines 55 mm apart (a glancing hit: the balls' centres pass 2 R - 2 mm apart) must still touch.
TEST(Islands, LoneBallsOnFreePathsMeetOnlyWhereThePathsMeet) {
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"balls", {ball("a", -1.0, -0.05, 1.0), ball("b", -1.0, 0.05, 1.0),
                                   ball("c", -0.5, 0.45, 0.8), ball("d", 0.5, 0.45 + 2 * kR - 2e-3, -0.8)}}};
  auto sim = simulate(scene(doc));
  long side_by_side = 0;
  sim->set_observer([&](const StepView& step) { side_by_side += step.balls[0] <= 1; });
  ASSERT_EQ(sim->advance(1.0), Status::Ok) << sim->diagnostic();
  int hits = 0;
  for (const Event& e : sim->events())
    if (e.kind == "contact_begin" && e.bodies == std::vector<std::string>{"c", "d"}) ++hits;
  std::printf("[ islands  ] two balls rolling side by side: %ld steps in 1 s; the glancing pair touched %d time(s)\n",
              side_by_side, hits);
  EXPECT_LT(side_by_side, 30);
  EXPECT_EQ(hits, 1);
  EXPECT_LT(std::abs(position(sim->state().x, 0).z + 0.05), 1e-9);  // a and b rolled straight: they never touched
}

// s: when balls a and b of the scene first touch within `duration`, every ball integrated in one system; -1 if never.
double single_system_touch(nlohmann::json doc, const std::string& a, const std::string& b, double duration) {
  doc["model"] = {{"islands", false}};
  auto single = simulate(scene(doc));
  EXPECT_EQ(single->advance(duration), Status::Ok) << single->diagnostic();
  return event_time(*single, "contact_begin", a, b);
}

// A sliding ball's path is a parabola until its slip reaches its band (FreePath::steady_for): two balls sliding past
// each other 3 mm apart at 1.5 m/s get no look at each other, though their bend bound (2 m/s^2 each) would close
// the gap in 40 ms; a ball curving under side slip into one whose centre its straight line misses by 7 mm touches it
// when and where the single all-ball system has it touch.
TEST(Islands, SlidingBallsMeetWhereTheirParabolasMeet) {
  auto sliding = [](const std::string& id, double x, double z, Vec3 v, Vec3 w) {
    return nlohmann::json{{"id", id}, {"position", {x, kR, z}}, {"velocity", {v.x, v.y, v.z}},
                          {"angular_velocity", {w.x, w.y, w.z}}};
  };
  const double d_x = -0.1907, d_z = 0.2908 - 0.055;  // where the curving ball is at 0.12 s, 55 mm off
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"balls", {sliding("a", -0.2, -0.3, {1.5, 0, 0}, Vec3{0.0}),
                                   sliding("b", 0.2, -0.3 + 2 * kR + 3e-3, {-1.5, 0, 0}, Vec3{0.0}),
                                   sliding("c", -0.3, 0.3, {1.0, 0, 0}, {-30, 0, 0}), ball("d", d_x, d_z)}}};
  auto sim = simulate(scene(doc));
  long looks = 0;  // steps of the passing pair's islands that end where one of them is looked at again
  sim->set_observer([&](const StepView& step) { looks += step.balls[0] <= 1; });
  ASSERT_EQ(sim->advance(0.3), Status::Ok) << sim->diagnostic();
  const double hit = event_time(*sim, "contact_begin", "c", "d"), reference = single_system_touch(doc, "c", "d", 0.3);
  std::printf("[ islands  ] two balls sliding past each other: %ld steps in 0.3 s; the curving ball touched at %.9f s "
              "(single system %.9f s)\n", looks, hit, reference);
  EXPECT_GT(reference, 0.1);
  EXPECT_NEAR(hit, reference, 1e-7);
  EXPECT_EQ(event_time(*sim, "contact_begin", "a", "b"), -1.0);
  EXPECT_LT(looks, 20);
}

// Its parabola holds only until the slip reaches its band: a stun shot that slides for 0.15 s and then rolls, its
// deceleration falling twentyfold, reaches a resting ball at 0.23 s, 3 mm further than its sliding parabola gets by
// then. It touches it when the single all-ball system has it touch.
TEST(Islands, ABallThatStopsSlidingIsFollowedAsItRolls) {
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"balls", {{{"id", "a"}, {"position", {0.0, kR, 0.0}}, {"velocity", {1.0, 0, 0}}}}}};
  auto alone = simulate(scene(doc));
  ASSERT_EQ(alone->advance(0.23), Status::Ok) << alone->diagnostic();
  const double reached = position(alone->state().x, 0).x;
  doc["balls"].push_back(ball("d", reached + 2 * kR, 0.0));
  auto sim = simulate(scene(doc));
  ASSERT_EQ(sim->advance(0.3), Status::Ok) << sim->diagnostic();
  const double hit = event_time(*sim, "contact_begin", "a", "d"), reference = single_system_touch(doc, "a", "d", 0.3);
  std::printf("[ islands  ] the stun shot reached the resting ball at %.9f s (single system %.9f s)\n", hit, reference);
  EXPECT_NEAR(reference, 0.23, 1e-3);
  EXPECT_NEAR(hit, reference, 1e-7);
}

// The break split into islands: no contact between islands may be missed. A missed one would let two balls pass
// through each other; the deepest ball-ball contact seen in frames of 1/240 s stays at the Hertz depth of the
// hardest collision (about 1 mm at 11 m/s), far from the 57 mm of a pass-through.
TEST(Islands, BreakMissesNoContactBetweenIslands) {
  auto sim = simulate(load_scene(preset("bench/s8_break.json")));
  double deepest = 0;
  size_t most_islands = 0;
  while (sim->time() < 3.0) {
    ASSERT_EQ(sim->advance(1.0 / 240), Status::Ok) << sim->diagnostic();
    most_islands = std::max(most_islands, sim->island_balls().size());
    for (const Contact& c : sim->contacts())
      if (c.other_ball >= 0) deepest = std::max(deepest, c.depth);
  }
  std::printf("[ islands  ] up to %zu islands; deepest ball-ball contact %.3g mm\n", most_islands, deepest * 1e3);
  EXPECT_GT(most_islands, 8u);  // the break does split up
  EXPECT_LT(deepest, 2e-3);
}

// A step's right-hand side looks only at the pairs its cap listed (StepContacts::near, contacts.hpp). That holds only
// if no other pair touches within the step: over the break's first 0.3 s (the rack, then balls spreading past each
// other), every pair that overlaps anywhere on a step's interpolant is listed as near or as left out of the step, by
// the cap run again at the step's start over the step's length.
TEST(Islands, StepListsHoldEveryPairThatTouchesInTheStep) {
  auto sim = simulate(load_scene(preset("bench/s8_break.json")));
  long steps = 0, touching = 0;
  sim->set_observer([&](const StepView& step) {
    const State& flags = step.flags;
    StepContacts lists;
    const ModelIndex index(step.model);
    BroadPhase broad;
    StateVector x0;
    step.state_at(step.t0, x0);
    time_to_possible_contact(step.model, index, flags, x0.data(), step.t1 - step.t0, broad, &lists);
    if (!lists.near_known) return;  // the step did not use the lists either
    ++steps;
    StateVector x;
    for (int k = 0; k <= 8; ++k) {
      step.state_at(step.t0 + (step.t1 - step.t0) * k / 8, x);
      for (int i = 0; i < flags.ball_count(); ++i)
        for (int j = i + 1; j < flags.ball_count(); ++j) {
          if (!flags.in_play[i] || !flags.in_play[j] || (flags.sleeping(i) && flags.sleeping(j))) continue;
          if (glm::length(position(x, i) - position(x, j)) >= 2 * kR) continue;
          ++touching;
          auto has = [&](const std::vector<ContactKey>& keys, ContactKey key) {
            return std::find(keys.begin(), keys.end(), key) != keys.end();
          };
          EXPECT_TRUE(has(lists.near, {i, j}) || has(lists.near, {j, i}) || has(lists.separated, {i, j}))
              << "balls " << step.model.balls[i].id << " and " << step.model.balls[j].id << " touch at t = "
              << step.t0 + (step.t1 - step.t0) * k / 8 << " s, in no list of the step from " << step.t0 << " s";
        }
    }
  });
  advance_to(*sim, 0.3);
  std::printf("[ islands  ] %ld steps with pair lists, %ld touching pairs checked\n", steps, touching);
  EXPECT_GT(touching, 1000);
}

// Two shots on opposite sides of the table, each a cue ball into an object ball: with islands each pair steps on
// its own, and every ball ends where the single system of all four ends, to the tolerance's level.
TEST(Islands, SplitShotEndsWhereTheSingleSystemEnds) {
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"balls", {ball("cue1", -0.9, -0.3, 1.5), ball("obj1", -0.5, -0.3),
                                   ball("cue2", 0.9, 0.3, -1.2, 0.1), ball("obj2", 0.5, 0.32)}}};
  auto split = simulate(scene(doc));
  doc["model"] = {{"islands", false}};
  auto single = simulate(scene(doc));
  advance_to(*split, 3.0);
  advance_to(*single, 3.0);
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    worst = std::max(worst, glm::length(position(split->state().x, i) - position(single->state().x, i)));
  std::printf("[ islands  ] split %ld steps, single %ld; largest position difference %.2e m\n", split->stats().steps,
              single->stats().steps, worst);
  EXPECT_GT(glm::length(position(split->state().x, 1) - Vec3(-0.5, kR, -0.3)), 0.1);  // the object balls moved
  EXPECT_LT(worst, 1e-5);
}

// Newton's cradle (the bench's S5): the four balls hanging still under their anchors sleep from the start, so only
// the released ball is integrated while it swings (45 steps, not the ~230 of a resting four-ball island held to 1 ms
// steps by its 10 um gaps); the swinging ball wakes them, and the impulse still runs through to the last ball. A ball
// held still off the vertical, on a rod standing up from its anchor, or in the air without a rod must not sleep: the
// first would swing, the others fall.
TEST(Islands, BallsHeldStillSleepUntilHit) {
  const Scene s = load_scene(preset("bench/s5_cradle.json"));
  auto sim = simulate(s);
  for (int i = 1; i < 5; ++i) EXPECT_TRUE(sim->state().sleeping(i)) << "ball " << i + 1;
  EXPECT_FALSE(sim->state().sleeping(0));  // at rest at 30 degrees: about to swing
  EXPECT_EQ(islands_of(*sim), (std::vector<std::vector<int>>{{0}}));
  ASSERT_EQ(sim->advance(0.2), Status::Ok) << sim->diagnostic();
  EXPECT_LT(sim->stats().steps, 60);
  ASSERT_EQ(sim->advance(s.duration - 0.2), Status::Ok) << sim->diagnostic();
  // Where the plain path (every ball integrated all along) ends, to well within the 1e-7 tolerance.
  auto plain = simulate(load_scene(preset("bench/s5_cradle.json"), kEveryBallIntegrated));
  ASSERT_EQ(plain->advance(s.duration), Status::Ok) << plain->diagnostic();
  for (int i = 0; i < 5; ++i) {
    EXPECT_LT(glm::length(position(sim->state().x, i) - position(plain->state().x, i)), 1e-8) << "ball " << i + 1;
    EXPECT_LT(glm::length(velocity(sim->state().x, i) - velocity(plain->state().x, i)), 1e-7) << "ball " << i + 1;
  }
  EXPECT_GT(velocity(sim->state().x, 4).x, 0.5);  // ball 5 flies off, swinging up

  nlohmann::json doc = {{"balls", {{{"id", "up"}, {"position", {0, 0.2, 0}}}}},
                        {"rods", {{{"ball", "up"}, {"anchor", {0, 0, 0}}}}}};
  EXPECT_FALSE(simulate(scene(doc))->state().sleeping(0));
  doc["rods"][0]["anchor"] = {0.001, 0.4, 0};  // hanging 0.29 degrees off the vertical: pulled back at 0.05 m/s^2
  EXPECT_FALSE(simulate(scene(doc))->state().sleeping(0));
  doc["rods"][0]["anchor"] = {0, 0.4, 0};
  EXPECT_TRUE(simulate(scene(doc))->state().sleeping(0));
  // Without a rod: a ball at rest in the air falls, one at rest in free space without gravity stays.
  doc.erase("rods");
  EXPECT_FALSE(simulate(scene(doc))->state().sleeping(0));
  doc["gravity"] = {0, 0, 0};
  EXPECT_TRUE(simulate(scene(doc))->state().sleeping(0));
}

// How a contact's steps go does not depend on where the step before its onset happened to end. The cradle's fast path
// reaches the touch by a step cut 0.5 us short of it by the step cap, the plain path by a 0.3 ms one; from the onset
// on, both take the same steps through the chain (they began with 2.2 us against 5.7 us steps, and the fast path
// ended 2.7x further off).
TEST(Islands, ContactStepsDoNotDependOnTheStepBeforeTheOnset) {
  auto chain_steps = [](const std::vector<std::string>& overrides) {
    auto sim = simulate(load_scene(preset("bench/s5_cradle.json"), overrides));
    std::vector<std::pair<double, double>> steps;  // (start, length) of every step that moves ball 2
    sim->set_observer([&](const StepView& step) {
      if (std::binary_search(step.balls.begin(), step.balls.end(), 1)) steps.emplace_back(step.t0, step.t1 - step.t0);
    });
    EXPECT_EQ(sim->advance(0.2295), Status::Ok) << sim->diagnostic();
    const double onset = event_time(*sim, "contact_begin", "1", "2");
    std::vector<double> lengths;
    for (const auto& [start, length] : steps)
      if (start >= onset - 1e-12 && lengths.size() < 12) lengths.push_back(length);
    return lengths;
  };
  const auto fast = chain_steps({});
  const auto plain = chain_steps(kEveryBallIntegrated);
  ASSERT_EQ(fast.size(), 12u);
  ASSERT_EQ(plain.size(), 12u);
  for (size_t k = 0; k < fast.size(); ++k) EXPECT_NEAR(fast[k], plain[k], 1e-3 * plain[k]) << "step " << k;
}

// The bench's S2 (free space, no gravity): the resting object ball sleeps until the cue ball reaches it, and the cut
// ends where the plain path ends it.
TEST(Islands, BallAtRestInFreeSpaceSleepsUntilHit) {
  const Scene s = load_scene(preset("bench/s2_glancing.json"));
  auto sim = simulate(s);
  EXPECT_TRUE(sim->state().sleeping(1));
  EXPECT_EQ(islands_of(*sim), (std::vector<std::vector<int>>{{0}}));
  ASSERT_EQ(sim->advance(s.duration), Status::Ok) << sim->diagnostic();
  auto plain = simulate(load_scene(preset("bench/s2_glancing.json"), kEveryBallIntegrated));
  ASSERT_EQ(plain->advance(s.duration), Status::Ok) << plain->diagnostic();
  EXPECT_GT(glm::length(velocity(sim->state().x, 1)), 0.1);  // the object ball was hit
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT(glm::length(position(sim->state().x, i) - position(plain->state().x, i)), 1e-9) << "ball " << i;
    EXPECT_LT(glm::length(velocity(sim->state().x, i) - velocity(plain->state().x, i)), 1e-8) << "ball " << i;
  }
}

}  // namespace
}  // namespace shotlab::test
