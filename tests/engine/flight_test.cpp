// The flight (Options::flight_regime, regimes.hpp): a ball touching nothing moves in closed form under gravity, against
// the projectile's textbook motion, and only while it touches nothing.
#include <cmath>
#include <random>

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

// A ball thrown over a rail leaves play below the table's edge, at the end of one long closed-form step. Read at
// every millisecond, it flies on its path until then and stays where it left from then on: the step's interpolant
// froze it from the step's start (a user trial's trajectory file had it jump 12 cm in 1 ms, 0.16 s early).
TEST(Flight, ABallLeavingPlayMovesOnItsPathUntilItLeaves) {
  nlohmann::json doc = {{"table", {{"type", "pool"}}},
                        {"balls", {{{"id", "b"}, {"position", {1.0, 0.15, 0.0}}, {"velocity", {2.0, 1.0, 0.0}}}}}};
  auto sim = simulate(scene(doc));
  std::vector<std::pair<double, Vec3>> seen;
  std::vector<Motion> motions;
  while (sim->time() < 1.0) {
    ASSERT_EQ(sim->advance(1e-3), Status::Ok) << sim->diagnostic();
    seen.emplace_back(sim->time(), position(sim->state().x, 0));
    motions.push_back(sim->motion(0));
  }
  const double left = event_time(*sim, "off_table", "b");
  ASSERT_LT(left, 0.9) << "the ball leaves play within the second";
  EXPECT_EQ(sim->motion(0), Motion::OffTable) << "over the rail, not into a pocket (a user trial read \"pocketed\")";
  EXPECT_LT(sim->stats().steps, 40) << "the flight is a few closed-form steps";
  const Vec3 frozen = seen.back().second;
  for (size_t k = 1; k < seen.size(); ++k) {
    const auto& [t, p] = seen[k];
    if (t < left) {
      EXPECT_LT(glm::length(p - seen[k - 1].second), 0.01) << "at t = " << t << " s, before it leaves at " << left;
    } else {
      EXPECT_EQ(p, frozen) << "at t = " << t << " s, after it left at " << left;
      EXPECT_EQ(motions[k], Motion::OffTable) << "at t = " << t << " s, after it left at " << left;
    }
  }
}

// A hop that starts under the support gap (10 um, where a ball stops counting as on its support) and rises past it:
// the flight's step ends where the ball gets that far, so that the ball takes off and lands where the parabola
// crosses it, not unseen inside one step that starts and ends under it.
TEST(Flight, AHopPastTheSupportGapTakesOffAndLands) {
  const double gap0 = 2e-6, apex = 20e-6, support = 1e-5;  // m
  const double vy = std::sqrt(2 * kG * (apex - gap0));
  auto sim = simulate(scene(throw_scene(kR + gap0, {0.5, vy, 0}, {0, 0, -0.5 / kR})));
  advance_to(*sim, 0.01);
  // gap0 + vy t - g t^2 / 2 = support at the two roots.
  const double mid = vy / kG, half = std::sqrt(2 * (apex - support) / kG);
  EXPECT_NEAR(event_time(*sim, "airborne", "b"), mid - half, 1e-9);
  EXPECT_NEAR(event_time(*sim, "landed", "b"), mid + half, 1e-9);
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

// The step cap over a pocket (contacts.cpp, collider_closing_time): a ball whose centre is over the hole, flying under
// gravity (nothing across), comes no closer than contact_margin to the bed's rim or any other collider (the jaws, the
// cushions, the pocket's back: arc_wall_closing_time) before the time the cap gives, the path sampled exactly (the
// projectile's) at 2000 points up to it. Starts within 2 cm of the rim, 5 mm either side of resting height, at up to
// 3 m/s in any direction, those already touching something left out (most of the ones by the back): what the cap must
// get right where a ball rolls over a pocket's edge.
TEST(Flight, TheCapOverAPocketNeverPassesTheRim) {
  Prepared p = prepare(load_scene(preset("cut.json")));
  const ModelIndex index(p.model);
  const int bed = [&] {
    for (size_t c = 0; c < p.model.colliders.size(); ++c)
      if (p.model.colliders[c].name == "bed") return static_cast<int>(c);
    return -1;
  }();
  ASSERT_GE(bed, 0);
  const Shape& shape = p.model.colliders[bed].shape;
  const auto* plane = std::get_if<BoundedPlane>(&shape);
  ASSERT_TRUE(plane && !plane->holes.empty());
  const Hole hole = plane->holes.front();
  State& state = p.state;
  state.rolling_on.assign(state.ball_count(), -1), state.sliding_on.assign(state.ball_count(), -1);
  for (int i = 1; i < state.ball_count(); ++i) state.in_play[i] = 0;
  std::mt19937_64 rng(34);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double margin = p.model.options.contact_margin, g = glm::length(p.model.options.gravity);
  int capped = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const double angle = M_PI * unit(rng), from_rim = 0.01 * (1.0 + unit(rng)), height = kR + 0.005 * unit(rng);
    const Vec3 p0 = hole.center + Vec3{(hole.radius - from_rim) * std::cos(angle), height, (hole.radius - from_rim) * std::sin(angle)};
    const Vec3 v0 = 3.0 * Vec3{unit(rng), unit(rng), unit(rng)} / std::sqrt(3.0);
    const auto at = [&](double t) { return p0 + v0 * t + 0.5 * t * t * p.model.options.gravity; };
    bool near = false;  // touching something already: no cap to check
    for (const Collider& c : p.model.colliders)
      if (const auto pen = penetration(c.shape, p0, kR)) near = near || pen->depth > -margin;
    if (near || !penetration(shape, p0, kR)) continue;
    set_position(state.x, 0, p0);
    set_velocity(state.x, 0, v0);
    const double cap = collider_contact_time(p.model, index, state, state.x.data(), 0, 0.05, {g, 0.0});
    if (!(cap < 0.05)) continue;
    ++capped;
    for (int k = 0; k < 2000; ++k)
      for (const Collider& c : p.model.colliders) {  // the bed, and the jaws, cushions and back around the pocket
        const double t = cap * k / 2000.0;
        const auto now = penetration(c.shape, at(t), kR);
        ASSERT_TRUE(!now || now->depth < margin) << "trial " << trial << ": " << now->depth << " m into " << c.name
                                                 << " at t = " << t << " s, before the cap " << cap << " s";
      }
  }
  EXPECT_GT(capped, 500) << "the rim should bound most of these starts";
}

// The cap over a hole is never shorter than the plain one (D falls at most at |v|): the cut at 2 m/s without ball-ball
// friction once sent the object ball across the pocket's axis, where rho - D vanishes, and the step shrank to nothing
// (20 000 steps short of the next frame).
TEST(Flight, ABallFallingPastAPocketsAxisIsNotHeldBack) {
  auto sim = simulate(load_scene(preset("cut.json"), {"cue.speed=2", "materials.ball_ball.friction=0"}));
  run_until(*sim, 1.0, [] { return false; }, 1.0 / 60);
  EXPECT_FALSE(sim->state().in_play[1]) << "the object ball drops into the pocket";
  EXPECT_LT(sim->stats().steps, 1000);
}

// A ball dropped onto the bed releases it before it leaves it: the damped force reaches zero while the bed is still
// compressed, and from there on pushes nothing until the depth is gone. Only the release is a kink; no step is cut
// to end where the contact ends (docs/model.md#step-control), and the hop's top comes out as with the cut.
TEST(Flight, ALiftOffAfterTheReleaseIsNoKink) {
  auto sim = simulate(scene(throw_scene(kR + 0.01, {0, 0, 0}, {0, 0, 0})));
  std::vector<double> ends;
  sim->set_observer([&](const StepView& v) { ends.push_back(v.t1); });
  advance_to(*sim, 0.05);
  const double begin = event_time(*sim, "contact_begin", "b"), end = event_time(*sim, "contact_end", "b");
  ASSERT_GT(begin, 0);
  ASSERT_GT(end, begin);
  double nearest = 1;
  for (double t : ends) nearest = std::min(nearest, std::abs(t - end));
  EXPECT_GT(nearest, 1e-9) << "a step was cut to end at the lift-off";
  // After the lift-off the ball flies: its top against the rebound speed the lift-off gave it (the same drop again,
  // stopped there).
  sim = simulate(scene(throw_scene(kR + 0.01, {0, 0, 0}, {0, 0, 0})));
  advance_to(*sim, end);
  const double vy = velocity(sim->state().x, 0).y, y = position(sim->state().x, 0).y;
  ASSERT_GT(vy, 0);
  advance_to(*sim, end + vy / kG);
  EXPECT_NEAR(position(sim->state().x, 0).y, y + vy * vy / (2 * kG), 1e-10);
  EXPECT_NEAR(velocity(sim->state().x, 0).y, 0, 1e-9);
}

}  // namespace
}  // namespace shotlab::test
