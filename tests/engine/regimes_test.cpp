// The fast path's regimes (engine/regimes.cpp) against the full model they stand in for: a ball that rolls to rest
// in the closed-form rolling regime, has the decay tails of its speed and spin cut and then sleeps must end where the
// full model (every ball integrated with smoothed cloth friction, no sleeping) brings it.
#include <cstdio>
#include <limits>

#include "engine/free_path.hpp"
#include "engine/regimes.hpp"

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
  // Both at 3e-11: a spin's tolerance is a surface speed (stepper.hpp), and at 1e-10 the full model's own spin error
  // over 6 s of rolling moves it 3e-8 m (1e-8 m at 3e-11, in the same steps: its cloth friction sets them).
  d["integrator"]["abs_tol"] = d["integrator"]["rel_tol"] = 3e-11;
  if (!fast) d["model"] = {{"rolling_regime", false}, {"sliding_regime", false}, {"sleep_time", 0}};
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

// A stun shot with side spin dropped onto the cloth from 1 mm: it bounces, settles onto the bed (the sliding regime
// then holds it at the static sink), slides on a parabola into rolling and rolls on. At tolerance 1e-9 the sliding
// regime must not move the ball measurably (the full model's own error at 1e-7 is 1.7e-7 m here), and the slide must
// not cost the stability-limited steps of the bed contact's vertical mode (about 1500 rad/s: 1-3 ms steps).
TEST(Regimes, SlidingBallEndsWhereTheFullModelEnds) {
  nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR + 1e-3, 0}}, {"velocity", {2.0, 0, 0.3}},
                                     {"angular_velocity", {0, 20.0, 0}}}});
  auto run = [&](bool sliding_regime, double tol, bool* slid = nullptr) {
    nlohmann::json d = doc;
    d["model"] = {{"sliding_regime", sliding_regime}};
    d["integrator"]["abs_tol"] = d["integrator"]["rel_tol"] = tol;
    auto sim = simulate(scene(d));
    if (slid) sim->set_observer([&](const StepView& step) { *slid = *slid || step.state.sliding(0); });
    advance_to(*sim, 0.6);  // sliding lasts 2 v / (7 mu g) = 0.29 s
    return std::pair{sim->state().x, sim->stats().steps};
  };
  // Against the full model at 1e-12 (itself within 1.1e-8 m/s of the full model at 1e-14, measured), both runs at 1e-9
  // carry the integration error of 0.6 s of dropping, bouncing, sliding and rolling: a few 1e-8.
  bool slid = false;
  const auto [x, steps] = run(true, 1e-9, &slid);
  const auto [x_full, steps_full] = run(false, 1e-9);
  const auto [x_ref, steps_ref] = run(false, 1e-12);
  auto dp = [&](const StateVector& a) { return glm::length(position(a, 0) - position(x_ref, 0)); };
  auto dv = [&](const StateVector& a) { return glm::length(velocity(a, 0) - velocity(x_ref, 0)); };
  std::printf("[ slide    ] slid and rolled to %.6f m; %ld steps, %ld without the sliding regime; against the reference "
              "|dp| = %.2e m, |dv| = %.2e m/s (without: %.2e m, %.2e m/s)\n",
              x[0], steps, steps_full, dp(x), dv(x), dp(x_full), dv(x_full));
  EXPECT_TRUE(slid);
  EXPECT_GT(x[0], 0.8);
  // The regime adds no error of its own beyond the integration's.
  EXPECT_LT(dp(x), 1e-7);
  EXPECT_LT(dv(x), 1e-7);
  EXPECT_LT(dp(x), 3 * dp(x_full) + 1e-9);
  EXPECT_LT(dv(x), 3 * dv(x_full) + 1e-9);
  EXPECT_LT(steps * 5, steps_full * 4);
}

// A ball dropped from 1 mm onto the cloth, moving at 2 m/s with the given spin, seen at `until` s in the regime asked
// for: its velocity and position on the fast path at 1e-7, against the full model at 1e-12, must be as close as the
// full model's at 1e-7 are (within `dp_slack` m).
void expect_hop_as_close_as_the_full_model(const char* what, const Vec3& spin, double until, bool rolling,
                                           double dp_slack) {
  const nlohmann::json doc = cloth_scene({{{"id", "cue"},
                                           {"position", {0, kR + 1e-3, 0}},
                                           {"velocity", {2.0, 0, 0}},
                                           {"angular_velocity", {spin.x, spin.y, spin.z}}}});
  bool entered = false;
  auto run = [&](bool fast, double tol) {
    nlohmann::json d = doc;
    if (!fast) d["model"] = {{"sliding_regime", false}, {"rolling_regime", false}};
    d["integrator"]["abs_tol"] = d["integrator"]["rel_tol"] = tol;
    auto sim = simulate(scene(d));
    advance_to(*sim, until);
    if (fast) entered = rolling ? sim->state().rolling(0) : sim->state().sliding(0);
    return sim->state().x;
  };
  const StateVector ref = run(false, 1e-12), fast = run(true, 1e-7), full = run(false, 1e-7);
  auto dv = [&](const StateVector& x) { return glm::length(velocity(x, 0) - velocity(ref, 0)); };
  auto dp = [&](const StateVector& x) { return glm::length(position(x, 0) - position(ref, 0)); };
  std::printf("[ hop      ] %s, at %.1f s against the full model at 1e-12: fast path |dv| = %.2e m/s, |dp| = %.2e m; "
              "full model at 1e-7 %.2e m/s, %.2e m\n", what, until, dv(fast), dp(fast), dv(full), dp(full));
  EXPECT_TRUE(entered);
  EXPECT_LT(dv(fast), 3 * dv(full) + 1e-8);
  EXPECT_LT(dp(fast), 3 * dp(full) + dp_slack);
}

// A ball enters the sliding regime while its hop still has up to rest_speed (1e-3 m/s) of normal motion, and the
// rolling regime too. Each entry adds what the hop's normal force would still have done through the friction: the
// impulse (mu m v_n when sliding, mu_r m v_n when rolling) and, as that impulse comes over the hop and not at once, a
// shift of the position (Regimes::update_sliding). Sliding, seen at 0.2 s (the hop settles within 30 ms, the slide
// lasts 0.29 s): without either correction 3.3e-5 m/s and 5.6e-6 m off, without the position's 1.2e-7 m (measured);
// with both 1.6e-13 m/s and 8e-16 m.
TEST(Regimes, SlidingEntryKeepsTheHopsFrictionImpulse) {
  expect_hop_as_close_as_the_full_model("sliding", Vec3(0.0), 0.2, false, 1e-12);
}

// Rolling from the start (w = v / R), seen at 0.5 s: the rolling entry comes while the hop is still under way, and
// without the correction the fast path ended 7.8e-6 m/s and 4.2e-6 m off (measured); with it 2.7e-8 m/s and 1.3e-8 m,
// nearer than the full model at 1e-7 itself, whose stiff smoothed friction leaves 2e-6 m/s.
TEST(Regimes, RollingEntryKeepsTheHopsRollingResistance) {
  expect_hop_as_close_as_the_full_model("rolling", Vec3(0, 0, -2.0 / kR), 0.5, true, 1e-9);
}

// The rolling entry snaps away the slip that is left (under 1 % of rest_speed and under 10 abs_tol), which leaves a
// lasting difference from the full model in proportion to it. That must stay below the integration error at every
// tolerance: a stun shot at 2 m/s, sliding into rolling at 0.29 s and rolling on to 0.6 s, ends as close to the
// full model at 1e-13 on the fast path as on the full model, at 1e-8 and at 1e-11. With the 1 % bound alone (a slip
// of 1e-5 m/s snapped away) the fast path's error was 6.8e-8 at 1e-8 and 1.4e-7 at 1e-11, measured.
TEST(Regimes, RollingEntryErrorFallsWithTheTolerance) {
  const nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {2.0, 0, 0}}}});
  auto end = [&](bool fast, double tol) {
    nlohmann::json d = doc;
    if (!fast) d["model"] = {{"rolling_regime", false}, {"sliding_regime", false}, {"sleep_time", 0}};
    d["integrator"]["abs_tol"] = d["integrator"]["rel_tol"] = tol;
    auto sim = simulate(scene(d));
    advance_to(*sim, 0.6);
    EXPECT_EQ(sim->state().rolling(0), fast);
    return sim->state().x;
  };
  const StateVector ref = end(false, 1e-13);
  for (double tol : {1e-8, 1e-11}) {
    auto err = [&](const StateVector& x) {
      return std::max(glm::length(position(x, 0) - position(ref, 0)), glm::length(velocity(x, 0) - velocity(ref, 0)));
    };
    const double fast = err(end(true, tol)), full = err(end(false, tol));
    std::printf("[ entry    ] tolerance %.0e: error against the full model at 1e-13: fast path %.2e, full model %.2e "
                "(m and m/s)\n", tol, fast, full);
    EXPECT_LT(fast, 3 * full + 1e-3 * tol);
  }
}

// Steps of a ball in a closed-form regime end where a friction term reaches the edge of its smoothing band (1/k =
// 1 mm/s of slip, speed or contact-patch speed at k = 1000 s/m). By MODEL.md's closed forms on the cloth (mu = 0.2,
// mu_r = 0.01, mu_sp = 0.0117): slip falls at 7/2 mu g = 6.867 m/s^2, a rolling ball's speed at mu_r g =
// 0.0981 m/s^2, the contact patch's speed R w_n at 5/2 mu_sp g = 0.2869 m/s^2.
TEST(Regimes, StepsEndAtTheSmoothingBandsEdge) {
  Prepared p = prepare(scene(cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}}, {{"id", "obj"}, {"position", {1, kR, 0}}}})));
  const ModelIndex index(p.model);
  State& s = p.state;
  s.sliding_on = {0, -1};
  s.rolling_on = {-1, -1};
  set_velocity(s.x, 0, Vec3(1.0, 0, 0));  // sliding without spin: slip 1 m/s
  bool constant = false;
  EXPECT_NEAR(time_to_band_edge(p.model, s, index, s.x.data(), &constant), (1.0 - 1e-3) / 6.867, 1e-5);
  EXPECT_FALSE(constant);  // obj is in the full model
  s.asleep = {0, 1};
  time_to_band_edge(p.model, s, index, s.x.data(), &constant);
  EXPECT_TRUE(constant);  // cue outside its bands, obj asleep: the island may step in closed form
  set_velocity(s.x, 0, Vec3(0.0));  // no slip left: no edge ahead
  time_to_band_edge(p.model, s, index, s.x.data(), &constant);
  EXPECT_FALSE(constant);  // a slider without slip would feel rolling resistance: no closed form
  s.asleep = {1, 0};
  s.rolling_on = {-1, 0};           // a ball rolling at 0.3 m/s with 1 m/s of patch speed: its speed's edge first
  set_velocity(s.x, 1, Vec3(0.3, 0, 0));
  set_spin(s.x, 1, Vec3(0, 1.0 / kR, -0.3 / kR));
  EXPECT_NEAR(time_to_band_edge(p.model, s, index, s.x.data()), (0.3 - 1e-3) / 0.0981, 1e-3);
  set_spin(s.x, 1, Vec3(0, 0.1 / kR, -0.3 / kR));  // with 0.1 m/s of patch speed, the spin's
  EXPECT_NEAR(time_to_band_edge(p.model, s, index, s.x.data()), (0.1 - 1e-3) / 0.2869, 1e-4);
  set_spin(s.x, 1, Vec3(0, 1e-3 / kR, -1e-3 / kR));  // on the bands' edges themselves: nothing left to cut
  set_velocity(s.x, 1, Vec3(1e-3, 0, 0));
  EXPECT_EQ(time_to_band_edge(p.model, s, index, s.x.data(), &constant), std::numeric_limits<double>::infinity());
  EXPECT_FALSE(constant);  // its speed and spin now decay inside their bands: no closed form
  std::vector<BandTail> tails;  // unless the caller follows those decays as tails (band_tail.hpp)
  const double to_stop = time_to_band_edge(p.model, s, index, s.x.data(), &constant, &tails);
  EXPECT_TRUE(constant);
  ASSERT_EQ(tails.size(), 2u);
  EXPECT_EQ(tails[0].kind, BandTail::Kind::Spin);
  EXPECT_EQ(tails[1].kind, BandTail::Kind::Speed);
  // The speed tail ends at the stop cut: from the edge (y0 = 1) to 5e-8 m/s, ln((2e4^2 - 1/3) / (2/3)) / (3 mu_r g k).
  EXPECT_NEAR(to_stop, std::log((4e8 - 1.0 / 3) / (2.0 / 3)) / (3 * 0.0981 * 1000), 1e-3);
  set_velocity(s.x, 1, Vec3(0.0));  // stopped rolling, the spin still decaying
  time_to_band_edge(p.model, s, index, s.x.data(), &constant);
  EXPECT_FALSE(constant);
  set_spin(s.x, 1, Vec3(0.0));  // at rest: constant (zero)
  time_to_band_edge(p.model, s, index, s.x.data(), &constant);
  EXPECT_TRUE(constant);
  s.rolling_on = {-1, -1};  // the full model
  time_to_band_edge(p.model, s, index, s.x.data(), &constant);
  EXPECT_FALSE(constant);
}

// A ball rolling outside its bands moves in closed form (MODEL.md eq. 3.6: x = v0 t - mu_r g t^2 / 2): each step
// costs one right-hand side, for the derivative at its end, where Cash-Karp's six stages would integrate the same
// polynomial. The position is that of the formula to round-off.
TEST(Regimes, RollingBallStepsInClosedForm) {
  const double v0 = 1.0, t = 2.0, a = 0.01 * 9.81;
  auto sim = simulate(scene(cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {v0, 0, 0}},
                                          {"angular_velocity", {0, 0, -v0 / kR}}}})));
  advance_to(*sim, t);
  const Stats& st = sim->stats();
  std::printf("[ closed   ] rolled %.9f m in %g s: %ld steps, %ld right-hand sides\n", position(sim->state().x, 0).x, t,
              st.steps, st.rhs_evaluations);
  ASSERT_TRUE(sim->state().rolling(0));
  EXPECT_NEAR(position(sim->state().x, 0).x, v0 * t - 0.5 * a * t * t, 1e-12);
  EXPECT_NEAR(velocity(sim->state().x, 0).x, v0 - a * t, 1e-13);
  EXPECT_LE(st.rhs_evaluations, st.steps + 2);
}

// A free path's steady part (free_path.hpp) ends before any regime snaps the velocity: where the rolling entry's slip
// (0.01 m/s here, with a raised rest_speed and tolerance) lies above the sliding band's edge (0.1 mm/s at a sharpness
// of 1e4 s/m), the steady part ends there, not at the edge. A stun shot checked in slices of 1 ms.
TEST(Regimes, ASteadyPathEndsBeforeTheRollingEntrysSnap) {
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"model", {{"friction_sharpness", 1e4}, {"rest_speed", 1.0}}},
                        {"integrator", {{"abs_tol", 1e-3}}},
                        {"balls", {{{"id", "a"}, {"position", {-1.0, kR, 0.0}}, {"velocity", {1.7218, 0, 0}}}}}};
  auto sim = simulate(scene(doc));
  ASSERT_EQ(sim->advance(0.01), Status::Ok) << sim->diagnostic();
  ASSERT_TRUE(sim->state().sliding(0));
  const ModelIndex index(sim->model());
  const auto path = free_path(sim->model(), sim->state(), sim->state().x.data(), 0, index, 1.0);
  ASSERT_TRUE(path.has_value());
  double snapped = -1;
  while (sim->time() < 0.4 && snapped < 0) {
    ASSERT_EQ(sim->advance(1e-3), Status::Ok) << sim->diagnostic();
    if (sim->state().rolling(0)) snapped = sim->time();
  }
  std::printf("[ regimes  ] steady until %.4f s; rolling from %.4f s at the latest\n", 0.01 + path->steady_for,
              snapped);
  ASSERT_GT(snapped, 0.0);
  EXPECT_GT(path->steady_for, 0.1);
  EXPECT_LE(0.01 + path->steady_for, snapped);
}

// A rolling ball's free path stays steady only while its speed is over rest_speed, where it may fall asleep (its
// velocity zeroed): with rest_speed raised to 5 cm/s, a ball rolling at 0.3 m/s on the cloth (slowing at mu_r g,
// MODEL.md eq. 3.6) is steady for (0.3 - 0.05) / (mu_r g) s; with sleep off, until its speed reaches the friction
// band's edge 1/k (1 mm/s at the default sharpness of 1000 s/m).
TEST(Regimes, ASteadyPathEndsWhereTheBallMayFallAsleep) {
  const double v0 = 0.3, rest = 0.05, a = 0.01 * 9.81;
  auto steady = [&](double sleep_time) {
    nlohmann::json doc = cloth_scene({{{"id", "cue"}, {"position", {0, kR, 0}}, {"velocity", {v0, 0, 0}},
                                       {"angular_velocity", {0, 0, -v0 / kR}}}});
    doc["model"] = {{"rest_speed", rest}, {"sleep_time", sleep_time}};
    auto sim = simulate(scene(doc));
    EXPECT_EQ(sim->advance(1e-3), Status::Ok) << sim->diagnostic();
    EXPECT_TRUE(sim->state().rolling(0));
    const ModelIndex index(sim->model());
    const auto path = free_path(sim->model(), sim->state(), sim->state().x.data(), 0, index, 10.0);
    EXPECT_TRUE(path.has_value());
    return path ? path->steady_for : -1.0;
  };
  const double speed = v0 - a * 1e-3;
  EXPECT_NEAR(steady(0.5), (speed - rest) / a, 1e-9);
  EXPECT_NEAR(steady(0.0), (speed - 1e-3) / a, 1e-9);
}

}  // namespace
}  // namespace shotlab::test
