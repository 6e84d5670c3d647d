// Hard impacts: a 15 m/s hit (no tunnelling through a ball or a cushion), a 0.999-offset glancing contact under the
// loosest setting of every method (not missed), contacts 100 times stiffer and undamped (still within the step
// limit, energy conserved).
#include "stability.hpp"

namespace shotlab::test {
namespace {

// Records in `deepest` the deepest contact (bed excluded) at the end of any accepted step, m.
void track_depth(Simulation& sim, double& deepest) {
  sim.set_observer([&deepest](const StepView& step) {
    for (const Contact& c : shotlab::contacts(step.model, step.state))
      if (c.other_ball >= 0 || step.model.colliders[c.collider].name != "bed") deepest = std::max(deepest, c.depth);
  });
}

// A cue ball at 15 m/s (beyond a powerful break, 11-13 m/s) hits a ball 0.3 m away (at 16 ms); the object ball goes
// on into the right cushion at about 14 m/s (at 101 ms). Hertz: the ball-ball depth peaks at
// (5 m_eff v^2 / (4 C_s))^(2/5) = 1.1 mm and the cushion depth at about 3 mm (C_s = 1e8); tunnelling would need a
// depth of a radius (28.6 mm). Between steps a tunnelling ball would not be seen inside the other at all, so the
// order of the balls is checked too: before the cushion (90 ms) the object ball must lead, and after it, it must
// have come back from the cushion.
TEST(Impact, FifteenMetresPerSecondDoesNotTunnel) {
  auto sim = simulate(scene({{"table", {{"type", "pool"}}},
                             {"balls", {{{"id", "cue"}, {"position", {-0.3, kR, 0}}, {"velocity", {15, 0, 0}}},
                                        {{"id", "object"}, {"position", {0.0, kR, 0}}}}}}));
  double deepest = 0;
  track_depth(*sim, deepest);
  run_frames(*sim, 0.09, 1.0 / 240, [] {});
  const StateVector& x = sim->state().x;
  EXPECT_GE(event_time(*sim, "contact_begin", "object"), 0) << "the collision did not happen";
  EXPECT_GT(position(x, 1).x - position(x, 0).x, 2 * kR) << "the cue ball is not behind the object ball";
  EXPECT_GT(velocity(x, 1).x, 0.9 * 15 * (1 + 0.9) / 2) << "the object ball did not take the cue ball's momentum";
  double furthest = 0;
  run_frames(*sim, 0.2, 1.0 / 240, [&] { furthest = std::max(furthest, position(sim->state().x, 1).x); });
  print_cost("15 m/s impact", *sim);
  std::printf("[ outcome  ] deepest contact %.3g m, furthest object ball centre x = %.4f m (cushion nose at 1.27 m)\n",
              deepest, furthest);
  EXPECT_LT(deepest, 0.2 * kR);
  EXPECT_GE(event_time(*sim, "contact_begin", "cushion-right"), 0) << "the object ball never reached the cushion";
  EXPECT_LT(furthest, 1.27 - 0.8 * kR) << "the object ball went into or through the cushion";
  EXPECT_TRUE(sim->state().in_play[1]) << "the object ball left the table";
  EXPECT_LT(velocity(sim->state().x, 1).x, 0) << "the object ball did not rebound from the cushion";
}

// S2 at offset 0.999: the balls overlap by at most 57 um for about 50 us. Every method at its loosest bench setting
// (tolerance 1e-3, or a fixed step of 1e-4 s) must see the contact and deflect both balls.
TEST(Impact, GlancingContactIsNotMissed) {
  const std::vector<std::pair<std::string, std::string>> settings = {
      {"euler", "integrator.fixed_step=1e-4"},   {"rk4", "integrator.fixed_step=1e-4"},
      {"cash_karp54", "integrator.abs_tol=1e-3"}, {"dopri5", "integrator.abs_tol=1e-3"},
      {"bulirsch_stoer", "integrator.abs_tol=1e-3"}, {"rosenbrock4", "integrator.abs_tol=1e-3"}};
  for (const auto& [method, setting] : settings) {
    SCOPED_TRACE(method);
    const Scene s = bench_scene("s2_glancing.json", {"balls.cue.position=[-0.06,0,0.05709285]",
                                                     "integrator.method=" + method, setting,
                                                     "integrator.rel_tol=1e-3"});
    auto sim = simulate(s);
    ASSERT_EQ(sim->advance(s.duration), Status::Ok) << sim->diagnostic();
    print_cost("glancing 0.999, " + method, *sim);
    EXPECT_GE(event_time(*sim, "contact_begin", "object"), 0) << "contact missed";
    // The object ball is pushed along the line of centres: away from the cue ball's side (-z).
    EXPECT_LT(velocity(sim->state().x, 1).z, -1e-4);
  }
}

// S1 at 8 m/s with the ball-ball stiffness x100 (5e10 N/m^1.5) and no damping: the contact is 100^(2/5) = 6.3 times
// shorter and the force 100^(2/5) = 6.3 times larger, yet the default integrator must finish within its default step
// limit, swap the velocities (VALIDATION R5) and conserve energy and momentum.
TEST(Impact, StiffUndampedContactConservesEnergy) {
  const Scene s = bench_scene("s1_head_on.json", {"balls.a.velocity=[8,0,0]", "materials.ball_ball.stiffness=5e10",
                                                  "materials.ball_ball.damping=0", "duration=0.001"});
  ASSERT_EQ(s.model.integrator.max_steps_per_call, IntegratorOptions{}.max_steps_per_call);
  auto sim = simulate(s);
  const double e0 = sim->energy().total();
  const Vec3 p0 = sim->momentum();
  run_frames(*sim, s.duration, 1.0 / 60, [] {});
  print_cost("stiffness x100, undamped, 8 m/s", *sim);
  const StateVector& x = sim->state().x;
  EXPECT_NEAR(velocity(x, 0).x, 0.0, 8e-6);
  EXPECT_NEAR(velocity(x, 1).x, 8.0, 8e-6);
  EXPECT_NEAR(sim->energy().total(), e0, 1e-6 * e0);
  EXPECT_NEAR(glm::length(sim->momentum() - p0), 0.0, 1e-6 * glm::length(p0));
}

// S4 with every contact 100 times stiffer and undamped: the ball now bounces on the cloth and off the cushion
// elastically; only friction removes energy. It must run to the end in 60 Hz frames within the default step limit,
// and the energy must never grow.
TEST(Impact, StiffUndampedTableNeverGainsEnergy) {
  std::vector<std::string> overrides;
  for (const char* m : {"ball_ball", "ball_cloth", "ball_cushion"}) {
    overrides.push_back(std::string("materials.") + m + ".stiffness=" + (std::string(m) == "ball_ball" ? "5e10" : "1e10"));
    overrides.push_back(std::string("materials.") + m + ".damping=0");
  }
  const Scene s = bench_scene("s4_cushion.json", overrides);
  auto sim = simulate(s);
  const double e0 = sim->energy().total();
  double gain = 0;
  run_frames(*sim, s.duration, 1.0 / 60, [&] { gain = std::max(gain, sim->energy().total() - e0); });
  print_cost("stiffness x100, undamped, cushion rebound", *sim);
  EXPECT_GE(event_time(*sim, "contact_begin", "cushion-right"), 0);
  EXPECT_LE(gain, 1e-6 * e0) << "energy grew";
}

// A whole exponent (here 2, Hunt-Crossley): Cash-Karp integrates the onset's polynomial force exactly, so its error
// estimate does not bound the step that starts the contact. A ball dropped from 0.1 m onto a plane must still bounce,
// on the fast and the plain path, and never sink more than a few times its static depth.
TEST(Impact, WholeExponentContactIsNotSteppedThrough) {
  for (const char* path : {"fast", "plain"}) {
    auto sim = simulate(scene({{"model", {{"path", path}}},
                               {"colliders", {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}},
                                               {"material", "ball_cloth"}}}},
                               {"materials", {{"ball_cloth", {{"exponent", 2}, {"stiffness", 3.91e10}, {"damping", 0.5},
                                                              {"damping_law", "hunt_crossley"}}}}},
                               {"balls", {{{"id", "b"}, {"position", {0, 0.1 + kR, 0}}}}}}));
    double lowest = 1;
    run_frames(*sim, 0.5, 1.0 / 240, [&] { lowest = std::min(lowest, position(sim->state().x, 0).y); });
    EXPECT_GT(lowest, kR - 1e-4) << path;  // the bounce's depth is about 20 um
    EXPECT_GT(position(sim->state().x, 0).y, kR) << path << ": the ball bounced";
  }
}

}  // namespace
}  // namespace shotlab::test
