// The rigid model (ContactModel::Rigid, docs/model.md#rigid-model) against ../shared/reference/VALIDATION.md's closed
// forms, each on a real scene run by the real engine with "contact": "rigid", and against what any model must keep:
// energy that never grows, balls that stay on the table, results that do not depend on how the caller slices time.
#include <cmath>
#include <fstream>

#include "engine/rigid_collide.hpp"
#include "shotlab/material.hpp"
#include "shotlab/diagnostics.hpp"
#include "shotlab/restitution.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

nlohmann::json rigid(nlohmann::json doc) {
  doc["model"]["contact"] = "rigid";
  return doc;
}

nlohmann::json ball(const std::string& id, double x, double vx, double topspin = 0) {
  // Topspin T = R w_top; rolling in +x has w_z = -v/R.
  return {{"id", id}, {"position", {x, kR, 0}}, {"velocity", {vx, 0, 0}}, {"angular_velocity", {0, 0, -topspin / kR}}};
}

SlideResult rigid_slide(double v0, double topspin) {
  const nlohmann::json cloth = {{"friction", 0.2}, {"rolling_resistance", 0}, {"spin_friction", 0}};
  return slide_to_roll(scene(rigid(cloth_scene(nlohmann::json::array({ball("cue", 0, v0, topspin)}), cloth))));
}

// R1 and R2: the slide's time, distance and final speed (VALIDATION.md's tolerance is 0.5 %; the rigid model's closed
// form meets them to round-off, so the test asks for the 5 digits VALIDATION.md quotes).
TEST(Rigid, R1R2_SlidesThenRolls) {
  struct Case {
    double topspin, tau, speed, distance;
  };
  for (const Case& c : {Case{0, 0.29125, 1.42857, 0.49928}, Case{-4, 0.87374, 0.28571, 0.99856},
                        Case{1, 0.14562, 1.71429, 0.27044}}) {
    const SlideResult r = rigid_slide(2.0, c.topspin);
    EXPECT_NEAR(r.tau, c.tau, 1e-5) << "topspin " << c.topspin;  // VALIDATION.md quotes 5 digits
    EXPECT_NEAR(r.speed, c.speed, 1e-5) << "topspin " << c.topspin;
    EXPECT_NEAR(r.distance, c.distance, 1e-5) << "topspin " << c.topspin;
  }
}

TEST(Rigid, R3_RollsToAStop) {
  auto sim = simulate(scene(rigid(cloth_scene(nlohmann::json::array({ball("cue", 0, 1.0, 1.0)}), {{"rolling_resistance", 0.01}}))));
  run_until(*sim, 12.0, [&] { return event_time(*sim, "stopped", "cue") >= 0; }, 0.1);
  EXPECT_NEAR(event_time(*sim, "stopped", "cue"), 10.194, 0.0005 * 10.194);
  EXPECT_NEAR(position(sim->state().x, 0).x, 5.097, 0.0005 * 5.097);
  EXPECT_TRUE(sim->at_rest());
}

TEST(Rigid, R4_VerticalSpinDecaysLinearlyAndDoesNotBendAPath) {
  const double w0 = 20.0, mu_sp = 0.0117, alpha = 5 * mu_sp * kG / (2 * kR);
  nlohmann::json top = ball("top", 0, 0);
  top["angular_velocity"] = {0, w0, 0};
  auto sim = simulate(scene(rigid(cloth_scene(nlohmann::json::array({top}), {{"spin_friction", mu_sp}}))));
  ASSERT_EQ(sim->advance(0.5 * w0 / alpha), Status::Ok);
  EXPECT_NEAR(spin(sim->state().x, 0).y, 0.5 * w0, 1e-9);
  EXPECT_EQ(sim->motion(0), Motion::Spinning);
  run_until(*sim, 2 * w0 / alpha, [&] { return event_time(*sim, "stopped", "top") >= 0; });
  EXPECT_NEAR(event_time(*sim, "stopped", "top"), w0 / alpha, 1e-9);

  nlohmann::json roller = ball("cue", 0, 1.0, 1.0);
  roller["angular_velocity"][1] = 30.0;
  auto straight = simulate(scene(rigid(cloth_scene(nlohmann::json::array({roller})))));
  run_until(*straight, 3.0, [&] { return position(straight->state().x, 0).x >= 1.0; }, 1e-3);
  EXPECT_LT(std::abs(position(straight->state().x, 0).z), 1e-4);
}

// R6 and R7: a rolling cue ball on a resting ball, frictionless balls whose linear damping gives zeta = 0.05 at the
// impact speed: restitution 0.9176 (R6, force clamped). Just after the impact the cue ball keeps (1 - e) / 2 v and the
// object ball takes (1 + e) / 2 v; once both roll, (5/7)(1 - e)/2 v + (2/7) v and (5/7)(1 + e)/2 v (R7).
TEST(Rigid, R6R7_HeadOnImpactRestitutionAndSpeeds) {
  const double v = 1.0, k = 5e8, m_eff = kM / 2, zeta = 0.05, e = 0.9176;
  auto doc = rigid(cloth_scene(nlohmann::json::array({ball("cue", -0.2, v, v), ball("ob", 0, 0)}),
                               {{"rolling_resistance", 0}}));
  doc["materials"]["ball_ball"] = {{"stiffness", k}, {"friction", 0},
                                   {"damping", zeta * std::pow(m_eff, 0.6) * std::pow(k, 0.4) * std::pow(v, 0.2)}};
  const Scene s = scene(doc);
  auto sim = simulate(s);
  run_until(*sim, 1.0, [&] { return event_time(*sim, "contact_begin", "cue", "ob") >= 0; }, 1e-3);
  const double hit = event_time(*sim, "contact_begin", "cue", "ob");
  EXPECT_NEAR(hit, (0.2 - 2 * kR) / v, 1e-12);  // rolling without resistance: at v all the way
  auto at_hit = simulate(s);
  ASSERT_EQ(at_hit->advance(hit), Status::Ok);  // the impulse is taken at its instant
  EXPECT_NEAR(velocity(at_hit->state().x, 0).x, (1 - e) / 2 * v, 0.002 * v);
  EXPECT_NEAR(velocity(at_hit->state().x, 1).x, (1 + e) / 2 * v, 0.002 * v);
  run_until(*sim, 5.0, [&] { return sim->motion(0) == Motion::Rolling && sim->motion(1) == Motion::Rolling; });
  EXPECT_NEAR(velocity(sim->state().x, 0).x, 5.0 / 7 * (1 - e) / 2 * v + 2.0 / 7 * v, 0.005 * v);
  EXPECT_NEAR(velocity(sim->state().x, 1).x, 5.0 / 7 * (1 + e) / 2 * v, 0.005 * v);
}

// A frictionless cushion sends a sliding, spinless ball back at its angle with the normal part times the cushion's
// restitution. A resting ball touches the nose at the WPA nose height 36.5 mm, so the contact normal is tilted down by
// asin((36.5 - 28.575) / 28.575) = 16.1 degrees: the closing speed along it is 0.8 cos(16.1) = 0.7686 m/s, for which the
// cushion's linear damping is set to zeta = 0.1 (R6: e = 0.8449, m_eff = m). The bed takes the vertical part of the
// push, so the ball comes back along the table at e times its 0.8 m/s across.
TEST(Rigid, AFrictionlessCushionReflectsWithItsRestitution) {
  const double k = 3e7, zeta = 0.1, e = 0.8449;
  const double closing = 0.8 * std::cos(std::asin((0.0365 - kR) / kR));
  auto doc = rigid({{"table", {{"type", "pool"}}}});
  doc["materials"]["ball_cushion"] = {
      {"stiffness", k}, {"friction", 0},
      {"damping", zeta * std::pow(kM, 0.6) * std::pow(k, 0.4) * std::pow(closing, 0.2)}};
  doc["materials"]["ball_cloth"] = {{"friction", 0}, {"rolling_resistance", 0}, {"spin_friction", 0}};
  doc["balls"] = {{{"id", "cue"}, {"position", {0, kR, 0.3}}, {"velocity", {0.6, 0, 0.8}}}};
  auto sim = simulate(scene(doc));
  run_until(*sim, 2.0, [&] { return event_time(*sim, "contact_begin", "cue") >= 0; }, 1e-3);
  ASSERT_EQ(sim->advance(0.01), Status::Ok);
  const Vec3 after = velocity(sim->state().x, 0);
  EXPECT_NEAR(after.x, 0.6, 1e-9);
  EXPECT_NEAR(after.z, -e * 0.8, 0.002);
}

// A rolling ball into a cushion whose nose is above its centre (the cushion preset, 45 degrees at 1.5 m/s): both
// frictions act through the impact, each on a slip the other changes, so the ball leaves the rebound's slide rolling
// within 1 % of the soft model's velocity, whose contact lasts 1.7 ms (taken one after the other, 6 % off).
TEST(Rigid, ACushionReboundRollsOnAsOnTheSoftModel) {
  const nlohmann::json doc = nlohmann::json::parse(std::ifstream(preset("cushion.json")));
  auto rolling_after_cushion = [](Simulation& sim) {
    run_until(sim, 2.0, [&] {
      const double hit = event_time(sim, "contact_begin", "cue", "cushion-back-right");
      return hit >= 0 && sim.time() > hit + 0.01 && sim.motion(0) == Motion::Rolling;
    }, 1e-3);
    return velocity(sim.state().x, 0);
  };
  auto soft = simulate(scene(doc)), hard = simulate(scene(rigid(doc)));
  const Vec3 vs = rolling_after_cushion(*soft), vr = rolling_after_cushion(*hard);
  EXPECT_GT(vs.z, 0.4);  // on its way back from the cushion
  EXPECT_LT(glm::length(vr - vs), 0.01 * glm::length(vs)) << vr.x << " " << vr.z << " against " << vs.x << " " << vs.z;
}

// An impulse at an event always parts the pair, even when round-off makes the closing speed a hair negative: else the
// same event would come back at the same instant until the event limit. And a cushion impact ends by work (energetic
// restitution), so that friction's vertical part, which the bed turns into speed across the cushion, cannot make an
// elastic cushion give back more energy than the ball brought.
TEST(Rigid, AnImpulseAlwaysPartsThePairAndGainsNoEnergy) {
  const BallSpec body = load_scene(preset("cut.json")).balls[0].spec;
  const Bounce slow{1.0, 1e-3};
  BallState a{Vec3{0.0}, Vec3{-1e-17, 0.0, 0.0}, Vec3{0.0}}, b{Vec3{2 * kR, 0.0, 0.0}, Vec3{0.0}, Vec3{0.0}};
  collide_balls(a, body, b, body, Vec3{1.0, 0.0, 0.0}, slow, default_ball_ball());
  EXPECT_GE(b.v.x - a.v.x, 1e-3 - 1e-15);
  const double tilt = std::asin((0.0365 - kR) / kR);
  const Vec3 n{0.0, -std::sin(tilt), std::cos(tilt)};  // from the nose's axis down to the centre
  BallState touching{Vec3{0.0}, Vec3{0.0, 0.0, 1e-17}, Vec3{0.0}};
  collide_rail(touching, body, n, slow, 0.2, 0.2);
  EXPECT_GE(glm::dot(touching.v, n), 1e-3 - 1e-12);
  auto energy = [&](const BallState& k) {
    return 0.5 * body.mass * glm::dot(k.v, k.v) + 0.5 * body.inertia() * glm::dot(k.w, k.w);
  };
  for (double e : {0.8, 0.98, 1.0}) {
    BallState stun{Vec3{0.0}, Vec3{0.0, 0.0, -1.0}, Vec3{0.0}};  // head-on at 1 m/s, no spin
    const double before = energy(stun);
    collide_rail(stun, body, n, Bounce{e, 1e-3}, 0.2, 0.2);
    EXPECT_LE(energy(stun), before) << "e = " << e;
    EXPECT_GT(stun.v.z, 0.0);
  }
}

// Any model: the break's energy never grows, every ball ends at rest on the bed or in a pocket, within the table.
TEST(Rigid, TheBreakLosesEnergyAndEndsAtRestOnTheTable) {
  nlohmann::json doc = nlohmann::json::parse(std::ifstream(preset("break.json")));
  doc["model"]["contact"] = "rigid";
  auto sim = simulate(scene(doc));
  double last = sim->energy().kinetic;
  for (int frame = 0; frame < 60 * 30 && !sim->at_rest(); ++frame) {
    ASSERT_EQ(sim->advance(1.0 / 60), Status::Ok) << sim->diagnostic();
    const double now = sim->energy().kinetic;
    EXPECT_LE(now, last + 1e-12) << "at t = " << sim->time();
    last = now;
  }
  ASSERT_TRUE(sim->at_rest());
  int pocketed = 0;
  for (int i = 0; i < sim->state().ball_count(); ++i) {
    const Vec3 p = position(sim->state().x, i);
    if (!sim->state().in_play[i]) {
      ++pocketed;
      continue;
    }
    EXPECT_NEAR(p.y, kR, 1e-4) << sim->model().balls[i].id;
    EXPECT_LT(std::abs(p.x), 1.27 - kR + 1e-9) << sim->model().balls[i].id;
    EXPECT_LT(std::abs(p.z), 0.635 - kR + 1e-9) << sim->model().balls[i].id;
  }
  EXPECT_LT(pocketed, 16);
  EXPECT_GT(sim->stats().steps, 50);  // events: the rack spreads through many collisions
}

// Frames of 1/30 s or one call give bit-identical results, as on the soft model; frames of 1/240 s the same results
// at the time they add up to.
TEST(Rigid, ResultsDoNotDependOnTheFrameLength) {
  nlohmann::json doc = nlohmann::json::parse(std::ifstream(preset("break.json")));
  doc["model"]["contact"] = "rigid";
  const Scene s = scene(doc);
  auto coarse = simulate(s), fine = simulate(s), whole = simulate(s);
  for (int f = 0; f < 30 * 4; ++f) ASSERT_EQ(coarse->advance(1.0 / 30), Status::Ok);
  for (int f = 0; f < 240 * 4; ++f) ASSERT_EQ(fine->advance(1.0 / 240), Status::Ok);
  ASSERT_EQ(whole->advance(coarse->time()), Status::Ok);
  EXPECT_EQ(coarse->state().x, whole->state().x);
  // 960 frames of 1/240 s add up to 4 s less exactly than 120 of 1/30 s (1e-13 s apart): a sliding ball's spin
  // changes at 170 rad/s^2 over that.
  ASSERT_NEAR(fine->time(), coarse->time(), 1e-12);
  EXPECT_EQ(fine->events().size(), coarse->events().size());
  for (size_t k = 0; k < coarse->state().x.size(); ++k) EXPECT_NEAR(fine->state().x[k], coarse->state().x[k], 1e-9);
  EXPECT_EQ(coarse->events().size(), whole->events().size());
}

// A ball at rest touching another, spun towards it, pushes it ahead instead of passing through it: the pair touches
// with no closing speed but accelerates together, which is a contact from that instant (engine/polynomial.hpp), and a
// collision that slow parts them at rest_speed.
// Both come to rest within 2 mm of where the soft model, whose contact lasts, leaves them.
TEST(Rigid, ABallSpunIntoATouchingBallPushesItAhead) {
  const nlohmann::json doc = cloth_scene(nlohmann::json::array({ball("cue", 0, 0, 2.0), ball("ob", 2 * kR, 0)}));
  auto sim = simulate(scene(rigid(doc))), soft = simulate(scene(doc));
  double closest = 1;
  run_until(*sim, 5.0, [&] {
    closest = std::min(closest, position(sim->state().x, 1).x - position(sim->state().x, 0).x);
    return sim->at_rest();
  }, 1e-3);
  EXPECT_GT(closest, 2 * kR - 1e-6);
  EXPECT_GT(position(sim->state().x, 1).x, 2 * kR + 0.1);  // pushed along
  run_until(*soft, 5.0, [&] { return soft->at_rest(); }, 0.1);
  for (int i : {0, 1}) EXPECT_NEAR(position(sim->state().x, i).x, position(soft->state().x, i).x, 2e-3) << i;
}

// The same against a cushion: a ball at rest touching the nose, spun into it, stays on the table.
TEST(Rigid, ABallSpunIntoACushionFromRestStaysOnTheTable) {
  auto doc = rigid({{"table", {{"type", "pool"}}}});
  doc["balls"] = {{{"id", "cue"}, {"position", {0.3, kR, 0}}}};
  const auto probe = simulate(scene(doc));
  const double y = position(probe->state().x, 0).y;
  double nose = 1;  // m: the centre's z touching the far side cushion's capsule over x = 0.3
  for (const Collider& c : probe->model().colliders)
    if (const auto* cap = std::get_if<Capsule>(&c.shape);
        cap && cap->a.z == cap->b.z && cap->a.z > 0 && std::min(cap->a.x, cap->b.x) < 0.3 && std::max(cap->a.x, cap->b.x) > 0.3)
      nose = cap->a.z - std::sqrt(std::pow(kR + cap->radius, 2) - std::pow(cap->a.y - y, 2));
  ASSERT_LT(nose, 1.0);
  doc["balls"][0]["position"] = {0.3, kR, nose};
  doc["balls"][0]["angular_velocity"] = {3.0 / kR, 0, 0};  // topspin towards +z
  auto sim = simulate(scene(doc));
  run_until(*sim, 3.0, [&] { return sim->at_rest(); }, 1e-2);
  EXPECT_TRUE(sim->state().in_play[0]);
  EXPECT_LT(position(sim->state().x, 0).z, nose + 1e-9);
  EXPECT_GE(event_time(*sim, "contact_begin", "cue"), 0);
}

// A path that curves across a cushion's line beyond its end and back across it alongside the cushion meets the
// cushion on the way back: the slab along the segment is entered twice. Rail at z = 0 from x = 0 to 1, reach 0.05 m;
// z(s) = 0.1 - s + s^2 re-enters |z| < 0.05 at s = (1 + sqrt(0.4)) / 2 where x = 1.6 - s = 0.784.
TEST(Rigid, ACurvedPathMeetsACushionAlongsideItAfterPassingItsEnd) {
  const Rail rail{0, Vec3{0.0}, Vec3{1.0, 0.0, 0.0}, 0.02};
  const Parabola p{Vec3{1.6, 0.0, 0.1}, Vec3{-1.0, 0.0, -1.0}, Vec3{0.0, 0.0, 2.0}};
  EXPECT_NEAR(rail_entry(p, 0.03, rail, 2.0), (1 + std::sqrt(0.4)) / 2, 1e-12);
}

// Balls of different radii on one bed touch with their centres at different heights: in the bed's plane they meet at
// sqrt((R1 + R2)^2 - (R1 - R2)^2) = 2 sqrt(R1 R2), not at R1 + R2.
TEST(Rigid, BallsOfDifferentSizesMeetWhereTheyTouch) {
  const double big = 0.0325, v = 1.0;
  nlohmann::json ob = ball("ob", 0.2, 0);
  ob["radius"] = big, ob["position"][1] = big;
  auto sim = simulate(scene(rigid(cloth_scene(nlohmann::json::array({ball("cue", 0, v, v), ob}), {{"rolling_resistance", 0}}))));
  run_until(*sim, 1.0, [&] { return event_time(*sim, "contact_begin", "cue", "ob") >= 0; }, 1e-3);
  EXPECT_NEAR(event_time(*sim, "contact_begin", "cue", "ob"), (0.2 - 2 * std::sqrt(kR * big)) / v, 1e-9);
}

// A ball rolling without resistance is searched beyond the search's horizon (1e4 s): at 0.1 mm/s it meets the
// cushion 1.24 m away after about 1.24e4 s instead of rolling through it.
TEST(Rigid, AnEventPastTheSearchHorizonIsFound) {
  auto doc = rigid({{"table", {{"type", "pool"}}}});
  doc["materials"]["ball_cloth"] = {{"rolling_resistance", 0}};
  doc["balls"] = {ball("cue", 0, 1e-4, 1e-4)};
  auto sim = simulate(scene(doc));
  ASSERT_EQ(sim->advance(2e4), Status::Ok) << sim->diagnostic();
  // The cushion's nose is at x = 1.27 m; its tilted contact has the centre within a few millimetres of 1.27 - R.
  EXPECT_GT(event_time(*sim, "contact_begin", "cue"), (1.27 - kR - 0.005) / 1e-4);
  EXPECT_LT(event_time(*sim, "contact_begin", "cue"), 1.27 / 1e-4);
  EXPECT_TRUE(sim->state().in_play[0]);
}

// Stopped by its event limit, the rigid model leaves the state at the last event it handled.
TEST(Rigid, TheEventLimitLeavesTheStateAtTheLastEvent) {
  nlohmann::json doc = nlohmann::json::parse(std::ifstream(preset("break.json")));
  doc["model"]["contact"] = "rigid";
  doc["integrator"]["max_steps_per_call"] = 5;
  auto sim = simulate(scene(doc));
  const State start = sim->state();
  ASSERT_EQ(sim->advance(1.0), Status::StepLimit);
  ASSERT_FALSE(sim->events().empty());
  EXPECT_GT(sim->time(), 0.0);
  EXPECT_EQ(sim->time(), sim->events().back().time);
  EXPECT_NE(sim->state().x, start.x);
  EXPECT_NE(sim->diagnostic().find("event limit"), std::string::npos);
}

// A scene the rigid model cannot run is refused with the field and the reason: a jump shot (the cue drives the ball
// into the bed hard enough to hop off it), a ball leaving the bed upwards, a rod, a hole in the bed that is no pocket, a
// rail below a ball's centre; a model name it does not know.
TEST(Rigid, RefusesScenesOffTheBed) {
  auto refused = [](nlohmann::json doc, const std::string& why) {
    doc["model"]["contact"] = "rigid";
    try {
      simulate(scene(doc));
      ADD_FAILURE() << "ran on the rigid model: " << why;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("model.contact"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  };
  refused(nlohmann::json::parse(std::ifstream(preset("jump.json"))), "hop");
  nlohmann::json up = ball("cue", 0, 1);
  up["velocity"][1] = 0.5;
  refused(cloth_scene(nlohmann::json::array({up})), "leaves the bed upwards");
  refused(nlohmann::json::parse(std::ifstream(preset("cradle.json"))), "rods");
  nlohmann::json holed = cloth_scene(nlohmann::json::array({ball("cue", 0, 1)}));
  holed["colliders"][0]["holes"] = {{{"center", {0.5, 0, 0}}, {"radius", 0.06}}};
  refused(holed, "hole at x = 0.5, z = 0 m that is not a pocket's");
  nlohmann::json low = cloth_scene(nlohmann::json::array({ball("cue", 0, 1)}));
  low["colliders"].push_back({{"type", "capsule"}, {"name", "kerb"}, {"a", {1, 0.01, -1}}, {"b", {1, 0.01, 1}}, {"radius", 0.01}});
  refused(low, "collider 'kerb' lies below ball 'cue''s centre");
  nlohmann::json deep = low;  // out of any ball's reach under the bed: nothing to refuse
  deep["colliders"][1]["a"][1] = deep["colliders"][1]["b"][1] = -0.1;
  EXPECT_NO_THROW(simulate(scene(rigid(deep))));
  nlohmann::json typo = rigid(cloth_scene(nlohmann::json::array({ball("cue", 0, 1)})));
  typo["model"]["contact"] = "hard";
  try {
    scene(typo);
    ADD_FAILURE() << "contact \"hard\" was taken";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("\"soft\" or \"rigid\""), std::string::npos) << e.what();
  }
}

// The restitution the rigid model reads off its table agrees with a head-on impact integrated at that speed: the
// built-in knots (Hertz contacts under either damping law) and knots worked out when met (another exponent).
TEST(Rigid, TabulatedRestitutionMatchesTheScaledImpact) {
  ContactMaterial hunt = default_ball_ball(), linear_spring = default_ball_cushion();
  hunt.damping_law = DampingLaw::HuntCrossley, hunt.damping = 0.2;  // s/m
  linear_spring.exponent = 1.0, linear_spring.stiffness = 3e5;     // N/m
  for (const ContactMaterial& m : {default_ball_ball(), default_ball_cushion(), default_ball_cloth(), hunt, linear_spring})
    for (double v : {0.013, 0.1, 0.77, 1.0, 3.3, 9.9}) {
      const double T = std::pow(kM / 2 * v * v / m.stiffness, 1 / (m.exponent + 1)) / v;
      const double g = m.damping_law == DampingLaw::Linear ? m.damping * T / (kM / 2) : m.damping * v;
      const double exact = scaled_impact(m.damping_law, m.exponent, g).restitution;
      EXPECT_NEAR(restitution_at(m, kM / 2, v), exact, 1e-5) << "v = " << v << ", exponent " << m.exponent;
    }
}

}  // namespace
}  // namespace shotlab::test
