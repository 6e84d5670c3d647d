// What a Simulation (simulation.hpp) runs: the soft model's World (world.hpp) or the rigid model's RigidWorld
// (rigid_world.hpp), chosen by Options::contact. Each method means what Simulation's of the same name says.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "shotlab/contact.hpp"
#include "shotlab/diagnostics.hpp"
#include "shotlab/event.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"
#include "shotlab/stats.hpp"
#include "shotlab/step_view.hpp"

namespace shotlab {

class Runner {
 public:
  virtual ~Runner() = default;
  virtual Status advance(double dt) = 0;
  virtual Status advance_on(double dt) = 0;
  virtual Status advance_within(double dt, double wall_seconds, bool new_window) = 0;
  virtual double time() const = 0;
  virtual const State& state() const = 0;
  virtual const Model& model() const = 0;
  virtual const std::vector<Event>& events() const = 0;
  virtual const Stats& stats() const = 0;
  virtual Status status() const = 0;
  virtual const std::string& diagnostic() const = 0;
  virtual Motion motion(int ball) const = 0;
  virtual Energy energy() const = 0;
  virtual Vec3 momentum() const = 0;
  virtual std::vector<Contact> contacts() const = 0;
  virtual bool at_rest() const = 0;
  virtual void set_observer(std::function<void(const StepView&)> observer) = 0;
  virtual std::vector<std::vector<int>> island_balls() const = 0;
};

}  // namespace shotlab
