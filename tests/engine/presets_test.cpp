// Every preset runs to its end; the thesis demonstrations (MODEL.md, "Reported results") show what the thesis
// describes; the shots named as players name them (stun, draw, follow) do what their names say.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "support.hpp"

namespace shotlab::test {
namespace {

std::vector<std::string> preset_files() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(SHOTLAB_SOURCE_DIR) + "/presets"))
    if (e.path().extension() == ".json") out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

class EveryPreset : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryPreset, RunsToItsEndWithFiniteState) {
  const Scene s = load_scene(preset(GetParam()));
  EXPECT_FALSE(s.description.empty()) << "a preset says what to look for";
  auto sim = simulate(s);
  advance_to(*sim, s.duration);
  EXPECT_NEAR(sim->time(), s.duration, 1e-9);
  for (double v : sim->state().x) ASSERT_TRUE(std::isfinite(v));
  std::printf("%s: %.2f s simulated, %ld steps, %ld rhs evaluations, %.3f s wall\n", GetParam().c_str(), s.duration,
              sim->stats().steps, sim->stats().rhs_evaluations, sim->stats().wall_seconds);
  // A contact begins, then ends, then may begin again: never reported as begun while it is on (a restart at a
  // located onset, where a ball left a regime or a sleeper woke, once reported it a second time a nanosecond later).
  // The first event of a pair may be its end: the contacts a scene starts with (balls resting on the bed) never began.
  std::map<std::vector<std::string>, std::string> last;
  for (const Event& e : sim->events()) {
    if (e.kind != "contact_begin" && e.kind != "contact_end") continue;
    std::vector<std::string> pair = e.bodies;
    std::sort(pair.begin(), pair.end());
    const auto it = last.find(pair);
    EXPECT_TRUE(it == last.end() || it->second != e.kind)
        << e.kind << " " << pair[0] << "-" << pair[1] << " at " << e.time << " s repeats the pair's last event";
    last[pair] = e.kind;
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, EveryPreset, ::testing::ValuesIn(preset_files()),
                         [](const auto& info) { return info.param.substr(0, info.param.size() - 5); });

TEST(Demonstrations, NewtonsCradle) {
  auto sim = simulate(load_scene(preset("cradle.json")));
  // Run until the first train of contacts has ended (each pair begun and ended), plus a millisecond.
  run_until(*sim, 0.5, [&] { return event_time(*sim, "contact_end", "b4", "b5") >= 0; }, 1e-3);
  ASSERT_EQ(sim->advance(1e-3), Status::Ok);
  double v[5];
  for (int i = 0; i < 5; ++i) v[i] = velocity(sim->state().x, i).x;
  EXPECT_GT(v[4], 0.5);  // the last ball flies furthest
  EXPECT_GT(v[3], 0.0);  // the one before it follows a little
  EXPECT_LT(v[3], 0.3 * v[4]);
  for (int i = 0; i < 3; ++i) EXPECT_LT(v[i], 0.0) << "ball " << i + 1 << " moves back";
  EXPECT_LT(v[0], v[1]);  // the first a bit more than the others
  EXPECT_LT(v[0], v[2]);
}

TEST(Demonstrations, JumpShotStopsBouncing) {
  auto sim = simulate(load_scene(preset("jump.json")));
  advance_to(*sim, 3.0);
  // The bounces of the jump, up to the first cushion (whose downward push may lift the ball off the cloth once more).
  std::vector<double> landings;
  for (const Event& e : sim->events()) {
    if (e.kind == "contact_begin" && e.bodies.back().rfind("cushion", 0) == 0) break;
    if (e.kind == "landed") landings.push_back(e.time);
  }
  ASSERT_GE(landings.size(), 2u);
  // Each flight is shorter than the one before (damping), and in the end the ball rolls.
  for (size_t k = 2; k < landings.size(); ++k) EXPECT_LT(landings[k] - landings[k - 1], landings[k - 1] - landings[k - 2]);
  EXPECT_EQ(sim->motion(0), Motion::Rolling);
}

TEST(Demonstrations, LowSideHitSlidesOnAParabolaThenRolls) {
  auto sim = simulate(load_scene(preset("sliding_parabola.json")));
  const double tau = [&] {
    run_until(*sim, 3.0, [&] { return event_time(*sim, "rolling", "cue") >= 0; }, 1e-3);
    return event_time(*sim, "rolling", "cue");
  }();
  ASSERT_GT(tau, 0.1);
  // While sliding the acceleration is constant (friction along a fixed slip direction): the path is a parabola, so
  // the midpoint of the sliding phase lies off the chord by |a| tau^2 / 8 projected across it.
  auto at = [&](double t) {
    auto replay = simulate(load_scene(preset("sliding_parabola.json")));
    advance_to(*replay, t);
    return position(replay->state().x, 0);
  };
  const Vec3 p0 = at(1e-3), p1 = at(tau / 2), p2 = at(tau - 1e-3);
  const Vec3 chord = glm::normalize(p2 - p0);
  const Vec3 off = (p1 - p0) - glm::dot(p1 - p0, chord) * chord;
  EXPECT_GT(glm::length(off), 1e-3);  // visibly curved (side spin bends it)
  run_until(*sim, 6.0, [&] { return sim->motion(0) == Motion::Stationary; }, 0.1);
  EXPECT_EQ(sim->motion(0), Motion::Stationary);
}

TEST(Demonstrations, CushionReboundSlidesThenRolls) {
  auto sim = simulate(load_scene(preset("cushion.json")));
  advance_to(*sim, 1.5);
  double hit = -1, slide = -1, roll = -1;
  for (const Event& e : sim->events()) {
    if (e.kind == "contact_begin" && e.bodies[1].rfind("cushion", 0) == 0 && hit < 0) hit = e.time;
    if (hit >= 0 && e.kind == "sliding" && slide < 0) slide = e.time;
    if (slide >= 0 && e.kind == "rolling" && roll < 0) roll = e.time;
  }
  ASSERT_GT(hit, 0);
  EXPECT_GE(slide, hit);
  EXPECT_GT(roll, slide);
  const Vec3 v = velocity(sim->state().x, 0);
  EXPECT_GT(v.z, 0.0);  // came in towards -z, leaves towards +z
  EXPECT_GT(v.x, 0.0);  // and keeps going along the rail
}

TEST(Demonstrations, FrozenBallsAtACushion) {
  auto sim = simulate(load_scene(preset("frozen.json")));
  advance_to(*sim, 0.5);
  const Vec3 v1 = velocity(sim->state().x, 0), v2 = velocity(sim->state().x, 1), v3 = velocity(sim->state().x, 2);
  EXPECT_GT(v1.z, 0.0) << "K1 leaves the cushion slightly";
  EXPECT_LT(v1.z, 0.2 * v2.z);
  EXPECT_GT(v3.z, 0.0) << "K3 is thrown back the way it came";
  // K2 leaves away from the cushion at an angle below 90 degrees to the rail.
  EXPECT_GT(v2.z, 0.0);
  EXPECT_GT(std::abs(v2.x), 0.0);
  // The collisions take time and overlap: K2 touches K1 and K3 at once.
  const double k23_end = event_time(*sim, "contact_end", "K2", "K3");
  EXPECT_GT(k23_end - event_time(*sim, "contact_begin", "K2", "K3"), 1e-4);
  EXPECT_LT(event_time(*sim, "contact_begin", "K1", "K2"), k23_end);
}

// The thesis's picture (its fig. 1.2): K1 and K2 frozen side by side along the cushion, K3 hits K2 full at 45 degrees;
// the soft cushion returns K2 into K3 for a second hit, K3 goes back the way it came, K2 forward below 90 degrees.
TEST(Demonstrations, ThesisFrozenBallsHitTwice) {
  auto sim = simulate(load_scene(preset("frozen_thesis.json")));
  advance_to(*sim, 0.5);
  int hits = 0;
  for (const Event& e : sim->events())
    if (e.kind == "contact_begin" && e.bodies.size() == 2 && e.bodies[0] == "K2" && e.bodies[1] == "K3") ++hits;
  EXPECT_EQ(hits, 2) << "K2 comes back out of the cushion and hits K3 again";
  const Vec3 v2 = velocity(sim->state().x, 1), v3 = velocity(sim->state().x, 2);
  EXPECT_LT(std::abs(std::atan2(v3.z, v3.x) * 180 / M_PI - 45), 10) << "K3 leaves roughly the way it came";
  EXPECT_GT(v2.z, 0.0);
  EXPECT_LT(v2.x, 0.0) << "K2 leaves forward, below 90 degrees to the rail";
}

// Three-cushion: the white contacts both object balls, and at least three cushions before the second.
TEST(Demonstrations, ThreeCushionShotScores) {
  auto sim = simulate(load_scene(preset("three_cushion.json")));
  advance_to(*sim, 8.0);
  std::vector<std::string> hits;  // what the white touches, in order, the bed left out
  for (const Event& e : sim->events())
    if (e.kind == "contact_begin" && e.bodies.size() == 2 && (e.bodies[0] == "white" || e.bodies[1] == "white")) {
      const std::string other = e.bodies[0] == "white" ? e.bodies[1] : e.bodies[0];
      if (other != "bed") hits.push_back(other);
    }
  int cushions = 0, balls = 0;
  for (const std::string& h : hits) {
    if (h.rfind("cushion", 0) == 0) ++cushions;
    else if (++balls == 2) break;
  }
  EXPECT_EQ(balls, 2) << "the white reaches both object balls";
  EXPECT_GE(cushions, 3) << "three cushions before the second ball";
}

TEST(Demonstrations, SymmetricBreakStaysSymmetric) {
  auto sim = simulate(load_scene(preset("break_symmetric.json")));
  advance_to(*sim, 1.0);
  const Model& m = sim->model();
  const auto& x = sim->state().x;
  // Mirror pairs across the long axis (z -> -z) in rack numbering: rows 1 | 2 3 | 4 5 6 | 7 8 9 10 | 11 ... 15.
  const std::pair<const char*, const char*> mirror[] = {{"2", "3"}, {"4", "6"}, {"7", "10"}, {"8", "9"}, {"11", "15"}, {"12", "14"}};
  for (const auto& [a, b] : mirror) {
    const Vec3 pa = position(x, m.ball_index(a)), pb = position(x, m.ball_index(b));
    EXPECT_NEAR(pa.x, pb.x, 1e-6) << a << " / " << b;
    EXPECT_NEAR(pa.z, -pb.z, 1e-6) << a << " / " << b;
  }
  for (const char* on_axis : {"cue", "1", "5", "13"}) EXPECT_NEAR(position(x, m.ball_index(on_axis)).z, 0.0, 1e-6);
  EXPECT_GT(std::abs(position(x, m.ball_index("11")).z), 0.2);  // and the rack did break up
}

TEST(Demonstrations, RealisticBreakIsSensitiveToMicronJitter) {
  const Scene a = load_scene(preset("break_realistic.json"));
  const Scene b = load_scene(preset("break_realistic.json"), {"rack.seed=8"});
  double largest_jitter_difference = 0;
  for (size_t i = 0; i < a.balls.size(); ++i)
    largest_jitter_difference = std::max(largest_jitter_difference, glm::length(a.balls[i].position - b.balls[i].position));
  EXPECT_LT(largest_jitter_difference, 2.0 * 1e-3 * kR * std::sqrt(2.0));
  auto sa = simulate(a), sb = simulate(b);
  advance_to(*sa, 1.0);
  advance_to(*sb, 1.0);
  double spread = 0;
  for (int i = 0; i < sa->state().ball_count(); ++i)
    spread = std::max(spread, glm::length(position(sa->state().x, i) - position(sb->state().x, i)));
  EXPECT_GT(spread, 0.01) << "micrometre changes in the rack change where balls are a second later by centimetres";
}

// The shots as players name them: a straight-in shot, the cue ball struck along the line of centres into the 1 ball.
// What the cue ball does: its speed just before and just after its first contact with the 1 ball, and where it comes
// to rest from the point where it met it, along its line (+ on past the contact, - back towards the player) and across.
struct StraightShot {
  double speed_before = 0, speed_after = 0;
  double along = 0, across = 0;
  bool cue_in_play = false, object_pocketed = false;
};

StraightShot straight_shot(const std::string& file) {
  const Scene s = load_scene(preset(file));
  auto sim = simulate(s);
  const int cue = sim->model().ball_index("cue");
  EXPECT_EQ(sim->model().ball_index("1"), 1);
  const Vec3 start = position(sim->state().x, cue);
  run_until(*sim, s.duration, [&] { return sim->at_rest(); }, 1.0 / 60);
  EXPECT_TRUE(sim->at_rest()) << file << " has not come to rest in its " << s.duration << " s";
  const double begin = event_time(*sim, "contact_begin", "cue", "1");
  const double end = event_time(*sim, "contact_end", "cue", "1");
  StraightShot r;
  if (begin <= 0 || end <= begin) {
    ADD_FAILURE() << file << ": the cue ball never met the 1 ball";
    return r;
  }
  // The state at the contact's begin and end, from the dense output of a replay.
  auto at = [&](double t) {
    auto replay = simulate(s);
    EXPECT_EQ(replay->advance(t), Status::Ok);
    return replay->state().x;
  };
  const auto x_begin = at(begin), x_end = at(end);
  const Vec3 contact = position(x_begin, cue), rest = position(sim->state().x, cue);
  const Vec3 line = glm::normalize(Vec3{contact.x - start.x, 0, contact.z - start.z});
  const Vec3 moved{rest.x - contact.x, 0, rest.z - contact.z};
  r.speed_before = glm::length(velocity(x_begin, cue));
  r.speed_after = glm::length(velocity(x_end, cue));
  r.along = glm::dot(moved, line);
  r.across = glm::length(moved - r.along * line);
  r.cue_in_play = sim->state().in_play[cue];
  r.object_pocketed = event_time(*sim, "pocketed", "1") >= 0;
  std::printf("%s: cue ball %.3f m/s before the contact, %.4f m/s after (%.2f %%); at rest %+.3f m along its line "
              "from the contact, %.3f m across\n",
              file.c_str(), r.speed_before, r.speed_after, 100 * r.speed_after / r.speed_before, r.along, r.across);
  return r;
}

// Stun: the cue ball arrives sliding without spin, hands its speed to the 1 ball and stops dead where it hit it.
TEST(Shots, StunStopsTheCueBallDeadAtTheContact) {
  const StraightShot r = straight_shot("stun.json");
  EXPECT_GT(r.speed_before, 1.0);
  EXPECT_LT(r.speed_after, 0.05 * r.speed_before);
  EXPECT_LT(std::hypot(r.along, r.across), 0.05);
  EXPECT_TRUE(r.cue_in_play);
  EXPECT_TRUE(r.object_pocketed);
}

// Draw: backspin left at the contact pulls the cue ball back towards the player.
TEST(Shots, DrawBringsTheCueBallBack) {
  const StraightShot r = straight_shot("draw.json");
  EXPECT_LT(r.along, -0.3);
  EXPECT_LT(r.across, 0.01);
  EXPECT_TRUE(r.cue_in_play);
  EXPECT_TRUE(r.object_pocketed);
}

// Follow: the rolling cue ball's topspin drives it on after the 1 ball, stopping short of the pocket.
TEST(Shots, FollowSendsTheCueBallOnAfterTheObjectBall) {
  const StraightShot r = straight_shot("follow.json");
  EXPECT_GT(r.along, 0.3);
  EXPECT_LT(r.across, 0.01);
  EXPECT_TRUE(r.cue_in_play) << "the cue ball followed the 1 ball into the pocket";
  EXPECT_TRUE(r.object_pocketed);
}

}  // namespace
}  // namespace shotlab::test
