// The simulation, as programs use it: a scene's model and initial state in, advance(dt) moves the clock to exactly
// t + dt, the state, events and counts out. Its workings (islands, steps, regimes) stay behind it in world.hpp; a step
// can be watched through StepView. Frames of 1/30 s, 1/240 s or one call give bit-identical results.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shotlab/diagnostics.hpp"
#include "shotlab/event.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"
#include "shotlab/stats.hpp"
#include "shotlab/step_view.hpp"

namespace shotlab {

class Runner;

// What keeps the rigid model (ContactModel::Rigid) from running a scene: a rod, a collider other than one flat, level
// bed and level capsules (cushions, jaws), gravity not straight down, a ball off its resting height on the bed or
// leaving it upwards. Empty when it can run.
std::string rigid_unsupported(const Model& model, const State& state);

class Simulation {
 public:
  // Runs the model's contact model (Options::contact); a scene the rigid model cannot run throws
  // std::invalid_argument saying why (rigid_unsupported, scene.hpp).
  Simulation(Model model, State initial);
  ~Simulation();
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Advance the clock by dt >= 0 s (a negative dt throws std::invalid_argument). Returns Ok, or why it stopped (then
  // status() stays so and diagnostic() says where and which balls; further calls do nothing).
  Status advance(double dt);
  // As advance(), but the step limit (max_steps_per_call) keeps counting from the previous call: a caller that stops
  // at sample times inside a window of its own counts the limit per window, however it samples.
  Status advance_on(double dt);
  // As advance(), but it may stop short of t + dt: once `wall_seconds` of wall time have passed (checked after each
  // step, one step at least) it stops at the latest time it can read every ball at; time() says where (it may stay
  // where it was while islands catch up with each other: call again). A window that draws frames keeps its frame
  // rate so. The steps do not depend on where calls stop: the results are those of any other slicing. With
  // `new_window` false the step limit counts on from the previous call, as advance_on(): a caller stopped short goes
  // on in the same window. The rigid model always does the whole dt (a break costs it under a millisecond).
  Status advance_within(double dt, double wall_seconds, bool new_window = true);

  double time() const;
  const State& state() const;
  const Model& model() const;
  const std::vector<Event>& events() const;
  const Stats& stats() const;
  Status status() const;
  const std::string& diagnostic() const;

  Motion motion(int ball) const;
  Energy energy() const;
  Vec3 momentum() const;
  std::vector<Contact> contacts() const;
  bool at_rest() const;  // every ball in play stationary (or out of play): nothing will move again

  // Called after every accepted step of any island (odeint's observer): step-size plots, per-contact counts.
  void set_observer(std::function<void(const StepView&)> observer);
  // The balls (scene indices) each island integrates together now.
  std::vector<std::vector<int>> island_balls() const;

 private:
  std::unique_ptr<Runner> world_;
};

}  // namespace shotlab
