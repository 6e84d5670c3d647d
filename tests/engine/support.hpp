// Test helpers: scenes written inline as JSON (parsed by the real scene reader), presets from presets/, runs.
#pragma once
#include <gtest/gtest.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab::test {

inline constexpr double kR = 0.028575;  // pool ball radius, m
inline constexpr double kM = 0.17;      // pool ball mass, kg
inline constexpr double kG = 9.81;

inline std::string preset(const std::string& name) { return std::string(SHOTLAB_SOURCE_DIR) + "/presets/" + name; }

inline Scene scene(const nlohmann::json& doc) { return parse_scene(doc, "test scene"); }

inline std::unique_ptr<Simulation> simulate(const Scene& s) {
  Prepared p = prepare(s);
  return std::make_unique<Simulation>(std::move(p.model), std::move(p.state));
}

// A flat, endless cloth (plane y = 0) and nothing else: the table terms without cushions.
inline nlohmann::json cloth_scene(const nlohmann::json& balls, const nlohmann::json& cloth = nlohmann::json::object()) {
  nlohmann::json doc = {
      {"colliders", {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "ball_cloth"}}}},
      {"balls", balls},
      {"integrator", {{"method", "dopri5"}, {"abs_tol", 1e-10}, {"rel_tol", 1e-10}, {"max_steps_per_call", 1000000}}}};
  doc["materials"]["ball_cloth"] = cloth;
  return doc;
}

// The first event of `kind` naming `body` (and `other`, if given), or -1.
inline double event_time(const Simulation& sim, const std::string& kind, const std::string& body,
                         const std::string& other = "") {
  auto names = [](const Event& e, const std::string& b) {
    return b.empty() || std::find(e.bodies.begin(), e.bodies.end(), b) != e.bodies.end();
  };
  for (const Event& e : sim.events())
    if (e.kind == kind && names(e, body) && names(e, other)) return e.time;
  return -1;
}

// Advances in slices (like display frames; the step limit counts per slice) until `done()` or time `limit`;
// fails the test if the simulation stops.
template <class Done>
void run_until(Simulation& sim, double limit, Done done, double slice = 1e-2) {
  while (sim.time() < limit - 1e-12 && !done()) {
    ASSERT_EQ(sim.advance(std::min(slice, limit - sim.time())), Status::Ok) << sim.diagnostic();
  }
}

// Ball "cue" of a scene from its start to its rolling event: when it begins to roll, how far it has gone along x and
// its speed then. Runs until the event, then replays exactly to that time (runs do not depend on slicing).
struct SlideResult {
  double tau, distance, speed;  // s, m, m/s
};
inline SlideResult slide_to_roll(const Scene& s) {
  auto sim = simulate(s);
  run_until(*sim, 3.0, [&] { return event_time(*sim, "rolling", "cue") >= 0; });
  const double tau = event_time(*sim, "rolling", "cue");
  auto replay = simulate(s);
  EXPECT_EQ(replay->advance(tau), Status::Ok);
  return {tau, position(replay->state().x, 0).x, velocity(replay->state().x, 0).x};
}

inline void advance_to(Simulation& sim, double t) {
  run_until(sim, t, [] { return false; }, 1.0 / 60);
}

}  // namespace shotlab::test
