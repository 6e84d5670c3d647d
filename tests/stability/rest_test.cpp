// Things that must not move: a ball resting on the cloth, a full rack, balls frozen against a cushion until hit.
// A resting contact is where a stiff Hertz spring and the friction smoothing meet an adaptive error control: any
// energy the integrator pumps in shows as drift, jitter of the motion state or a ball that creeps.
#include "stability.hpp"

namespace shotlab::test {
namespace {

// Largest distance of any ball from where it started, m.
double max_displacement(const Simulation& sim, const StateVector& x0) {
  double d = 0;
  for (int i = 0; i < sim.state().ball_count(); ++i)
    d = std::max(d, glm::length(position(sim.state().x, i) - position(x0, i)));
  return d;
}

// Runs a scene of balls at rest for `duration` s in 60 Hz frames and checks at every frame: no ball moved more than
// 1e-9 m, the total energy did not grow (beyond 1e-12 J of round-off), every ball is stationary; and no event
// (contact or motion change) ever fired.
void expect_stays_at_rest(const std::string& name, const Scene& scene, double duration) {
  auto sim = simulate(scene);
  const StateVector x0 = sim->state().x;
  const double e0 = sim->energy().total();
  double drift = 0, gain = 0;
  int moving_frames = 0;
  run_frames(*sim, duration, 1.0 / 60, [&] {
    drift = std::max(drift, max_displacement(*sim, x0));
    gain = std::max(gain, sim->energy().total() - e0);
    for (int i = 0; i < sim->state().ball_count(); ++i) moving_frames += sim->motion(i) != Motion::Stationary;
  });
  print_cost(name, *sim);
  std::printf("[ outcome  ] %s: max drift %.3g m, max energy gain %.3g J\n", name.c_str(), drift, gain);
  EXPECT_LT(drift, 1e-9);
  EXPECT_LE(gain, 1e-12);
  EXPECT_EQ(moving_frames, 0) << "frames where some ball was not stationary";
  EXPECT_TRUE(sim->events().empty()) << sim->events().size() << " events, the first: " << sim->events()[0].kind
                                     << " at " << sim->events()[0].time << " s";
}

TEST(Rest, BallOnTheClothFor60Seconds) {
  expect_stays_at_rest("ball at rest 60 s",
                       scene({{"table", {{"type", "pool"}}}, {"balls", {{{"id", "b"}, {"position", {0.3, kR, 0.2}}}}}}),
                       60.0);
}

// A frozen rack: neighbours touch at exactly zero depth, so a displacement of one ulp starts or ends a contact. The
// default integrator for 10 s, the other explicit adaptive methods for 1 s (rosenbrock4 is too slow for 16 balls).
TEST(Rest, FullRackStaysAtRest) {
  const nlohmann::json rack = {{"table", {{"type", "pool"}}},
                               {"rack", {{"type", "triangle"}}},
                               {"balls", {{{"id", "cue"}, {"position", {-0.635, kR, 0}}}}}};
  expect_stays_at_rest("rack at rest 10 s, default integrator", scene(rack), 10.0);
  for (const char* method : {"cash_karp54", "bulirsch_stoer"}) {
    SCOPED_TRACE(method);
    nlohmann::json doc = rack;
    doc["integrator"]["method"] = method;
    expect_stays_at_rest(std::string("rack at rest 1 s, ") + method, scene(doc), 1.0);
  }
}

// The thesis's motivating example (MODEL.md, reported result 1; presets/frozen.json): K1 frozen to the back
// cushion (-z), K2 frozen to K1, K3 comes straight at the cushion and hits K2 at a 45 degree cut.
TEST(Rest, FrozenBallsAgainstACushion) {
  const Scene s = load_scene(preset("frozen.json"));
  auto sim = simulate(s);
  const int k1 = sim->model().ball_index("K1"), k2 = sim->model().ball_index("K2"), k3 = sim->model().ball_index("K3");
  const Vec3 k1_start = position(sim->state().x, k1);
  const double k3_side = position(sim->state().x, k3).x - position(sim->state().x, k2).x;  // K3 comes from +x
  const double e0 = sim->energy().total();
  double k1_up = 0, k1_into_cushion = 0, energy_gain = 0;
  run_frames(*sim, 1.0, 1.0 / 240, [&] {
    const StateVector& x = sim->state().x;
    k1_up = std::max(k1_up, velocity(x, k1).y);
    k1_into_cushion = std::max(k1_into_cushion, k1_start.z - position(x, k1).z);
    energy_gain = std::max(energy_gain, sim->energy().total() - e0);
  });
  print_cost("frozen balls at a cushion, 1 s", *sim);
  const StateVector& x = sim->state().x;
  const Vec3 v2 = velocity(x, k2), v3 = velocity(x, k3);
  std::printf("[ outcome  ] K1 max upward speed %.3g m/s, max push into the cushion %.3g m; K2 leaves at (%.3f, %.3f) "
              "m/s, K3 at (%.3f, %.3f) m/s\n", k1_up, k1_into_cushion, v2.x, v2.z, v3.x, v3.z);
  // Nothing here adds energy: every contact is damped and every friction dissipates.
  EXPECT_LE(energy_gain, 1e-9);
  // K1 is pressed into the cushion, by the Hertz depth only (well under a millimetre), not through it.
  EXPECT_GT(k1_into_cushion, 0);
  EXPECT_LT(k1_into_cushion, 1e-3);
  // Friction with K2 gives K1 vertical speed: it hops (MODEL.md: "K1 bounces slightly off the cushion").
  EXPECT_GT(k1_up, 1e-3);
  // K3 is thrown back, away from the cushion (+z), the way it came; a free K2 would have let it pass on towards the
  // cushion (-z) at 45 degrees.
  EXPECT_GT(v3.z, 0);
  // The cut drives K2 into the stack and away from K3's side; the cushion returns the push, so K2 leaves along the
  // rail away from K3 and not into the cushion.
  EXPECT_LT(v2.x * k3_side, 0);
  EXPECT_GE(v2.z, -1e-3);
}

}  // namespace
}  // namespace shotlab::test
