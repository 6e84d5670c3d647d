// The friction sign switch (MODEL.md, appendix B): near zero slip the smoothed Coulomb friction acts like a stiff
// damper (rate 1.5 k a ~ 1e4 1/s on the cloth). An integrator that overshoots there makes the slip change sign
// every step and the motion state flicker between sliding and rolling.
#include "stability.hpp"

namespace shotlab::test {
namespace {

// Motion events of ball 0, in order.
std::vector<std::string> motion_events(const Simulation& sim) {
  std::vector<std::string> out;
  for (const Event& e : sim.events())
    if (e.kind == "sliding" || e.kind == "rolling" || e.kind == "spinning" || e.kind == "stopped") out.push_back(e.kind);
  return out;
}

// Slip speed |v + R y x w| of ball 0, m/s.
double slip(const Simulation& sim) {
  const StateVector& x = sim.state().x;
  return glm::length(velocity(x, 0) + sim.model().balls[0].radius * glm::cross(kUp, spin(x, 0)));
}

// A ball on the cloth rolling at 0.5 m/s with a slip of `initial_slip` m/s (less topspin than rolling needs), run
// for `duration` s: friction must remove the slip once and for all.
void expect_one_switch(const std::string& name, double initial_slip, double duration,
                       const std::vector<std::string>& expected) {
  const double v = 0.5;
  auto sim = simulate(scene({{"table", {{"type", "pool"}}},
                             {"balls", {{{"id", "b"}, {"position", {-1.0, kR, 0}}, {"velocity", {v, 0, 0}},
                                         {"angular_velocity", {0, 0, -(v - initial_slip) / kR}}}}}}));
  const double rest = sim->model().options.rest_speed;
  int slipping_frames_after_roll = 0;
  run_frames(*sim, duration, 1.0 / 240, [&] {
    if (event_time(*sim, "rolling", "b") >= 0 && sim->motion(0) == Motion::Rolling)
      slipping_frames_after_roll += slip(*sim) > rest;
  });
  print_cost(name, *sim);
  std::string seen;
  for (const std::string& e : motion_events(*sim)) seen += e + " ";
  std::printf("[ outcome  ] %s: motion events: %s\n", name.c_str(), seen.c_str());
  EXPECT_EQ(motion_events(*sim), expected);
  EXPECT_EQ(slipping_frames_after_roll, 0) << "rolling frames with slip above rest_speed";
}

// Slip of 2 mm/s: just above rest_speed (1 mm/s), inside the smoothing band of fricstep (1/k = 1 mm/s).
TEST(Slip, SmallSlipSettlesOnceIntoRolling) {
  expect_one_switch("slip 2 mm/s", 2e-3, 1.0, {"rolling"});
}

// A ball that starts rolling exactly (slip 0) decelerates to a stop: it must never be classed as sliding on the way.
TEST(Slip, PureRollingToAStopNeverSlides) {
  expect_one_switch("pure rolling to a stop", 0.0, 6.0, {"stopped"});
}

// S3, the stun shot: exactly one switch from sliding to rolling, at the closed-form time 2 v0 / (7 mu g) = 0.29125 s
// within the smoothing's shift (VALIDATION R1 allows 0.5 %).
TEST(Slip, StunShotSwitchesOnce) {
  const Scene s = bench_scene("s3_stun.json");
  auto sim = simulate(s);
  run_frames(*sim, s.duration, 1.0 / 60, [] {});
  print_cost("stun shot", *sim);
  EXPECT_EQ(motion_events(*sim), std::vector<std::string>{"rolling"});
  EXPECT_NEAR(event_time(*sim, "rolling", "cue"), 0.29125, 0.005 * 0.29125);
}

}  // namespace
}  // namespace shotlab::test
