// The friction rate limit (Options::friction_rate_limit, contact_force.hpp): under heavy load the smoothing band
// widens so that a stuck contact does not force 0.1 us steps. It must leave the outcome of hard contacts, where
// friction sticks and slips within milliseconds, as it was: compared here with the same shots run without a limit.
#include <cstdio>
#include <fstream>

#include "engine/contacts.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

TEST(FrictionRateLimit, BandWidensOnlyAboveTheLimit) {
  const Smoothing s{1000.0, 2e5};
  // On the cloth: mu m g = 0.2 * 0.17 * 9.81 N on the slip mobility 3.5 / m: rate 1.5 k mu g 3.5 = 1.03e4 1/s.
  EXPECT_EQ(sharpness_for(s, 0.2 * kM * kG, 3.5 / kM), 1000.0);
  // 3000 N into a cushion: the rate would be 1.5 * 1000 * 0.2 * 3000 * 3.5 / 0.17 = 1.85e7 1/s; it is held at 2e5.
  const double k = sharpness_for(s, 0.2 * 3000, 3.5 / kM);
  EXPECT_NEAR(1.5 * k * 0.2 * 3000 * 3.5 / kM, 2e5, 1e-6);
  EXPECT_EQ(sharpness_for({1000.0, 0.0}, 0.2 * 3000, 3.5 / kM), 1000.0);  // 0: no limit
}

struct Outcome {
  Vec3 v, w;
  long steps;
};

Outcome run(const nlohmann::json& doc, double limit, double until) {
  nlohmann::json d = doc;
  d["model"]["friction_rate_limit"] = limit;
  d["integrator"] = {{"abs_tol", 1e-9}, {"rel_tol", 1e-9}, {"max_steps_per_call", 1000000}};
  auto sim = simulate(scene(d));
  advance_to(*sim, until);
  return {velocity(sim->state().x, 0), spin(sim->state().x, 0), sim->stats().steps};
}

// Velocity and R w differences against the unlimited run, relative to the initial speed v0.
void expect_same_outcome(const std::string& name, const nlohmann::json& doc, double v0, double until) {
  const Outcome limited = run(doc, 2e5, until), plain = run(doc, 0.0, until);
  const double dv = glm::length(limited.v - plain.v) / v0, dw = kR * glm::length(limited.w - plain.w) / v0;
  std::printf("[ outcome  ] %s: |dv| / v0 = %.2e, R |dw| / v0 = %.2e; steps %ld with the limit, %ld without\n",
              name.c_str(), dv, dw, limited.steps, plain.steps);
  EXPECT_LT(dv, 2e-3) << name;
  EXPECT_LT(dw, 2e-3) << name;
  EXPECT_LT(limited.steps, plain.steps) << name;
}

// A ball with heavy top and side spin driven into the right cushion at 6 m/s, 30 degrees off the normal: the cushion
// grips the spinning ball (stick and slip at about 2500 N).
TEST(FrictionRateLimit, SpinningBallIntoCushionKeepsItsRebound) {
  const nlohmann::json doc = {
      {"table", {{"type", "pool"}}},
      {"balls", {{{"id", "cue"}, {"position", {1.0, kR, 0}}, {"velocity", {5.196, 0, 3.0}},
                  {"angular_velocity", {105.0, 80.0, -180.0}}}}}};
  expect_same_outcome("spinning ball into a cushion", doc, 6.0, 0.1);
}

// A cut at 8 m/s with "gearing" side spin: w_y = v n_z / R (n the contact normal, n_z = 0.02 / 2R) leaves the
// contact points nearly without slip, so ball-ball friction (up to about 2000 N of load) works inside its band.
TEST(FrictionRateLimit, GearedCutShotKeepsItsThrow) {
  const nlohmann::json doc = {
      {"table", {{"type", "pool"}}},
      {"balls", {{{"id", "cue"}, {"position", {-0.3, kR, 0.02}}, {"velocity", {8.0, 0, 0}},
                  {"angular_velocity", {0, 8.0 * 0.02 / (2 * kR) / kR, 0}}},
                 {{"id", "object"}, {"position", {0.0, kR, 0}}}}}};
  expect_same_outcome("geared cut shot", doc, 8.0, 0.06);
}

// The break: every ball of the rack pressed against its neighbours with thousands of newtons at once; 30 ms after
// the cue ball arrives.
TEST(FrictionRateLimit, BreakKeepsItsFirstMilliseconds) {
  nlohmann::json doc;
  {
    std::ifstream in(preset("bench/s8_break.json"));
    doc = nlohmann::json::parse(in);
  }
  expect_same_outcome("break, cue ball", doc, 11.0, 0.14);
}

}  // namespace
}  // namespace shotlab::test
