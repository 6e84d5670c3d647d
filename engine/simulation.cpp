#include "shotlab/simulation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "rigid_world.hpp"
#include "world.hpp"

namespace shotlab {

namespace {

std::unique_ptr<Runner> runner_for(Model model, State initial) {
  if (model.options.contact == ContactModel::Rigid)
    return std::make_unique<RigidWorld>(std::move(model), std::move(initial));
  return std::make_unique<World>(std::move(model), std::move(initial));
}

}  // namespace

Simulation::Simulation(Model model, State initial) : world_(runner_for(std::move(model), std::move(initial))) {}
Simulation::~Simulation() = default;

namespace {
// The clock only runs forward, by a finite time: the dense output of the last step cannot go back past its start.
double checked_dt(double dt) {
  if (!(dt >= 0) || !std::isfinite(dt))
    throw std::invalid_argument("Simulation::advance: dt must be a finite time >= 0 s, got " + std::to_string(dt));
  return dt;
}
}  // namespace

Status Simulation::advance(double dt) { return world_->advance(checked_dt(dt)); }
Status Simulation::advance_on(double dt) { return world_->advance_on(checked_dt(dt)); }
Status Simulation::advance_within(double dt, double wall_seconds, bool new_window) {
  if (std::isnan(wall_seconds))
    throw std::invalid_argument("Simulation::advance_within: wall_seconds must not be NaN");
  return world_->advance_within(checked_dt(dt), wall_seconds, new_window);
}
double Simulation::time() const { return world_->time(); }
const State& Simulation::state() const { return world_->state(); }
const Model& Simulation::model() const { return world_->model(); }
const std::vector<Event>& Simulation::events() const { return world_->events(); }
const Stats& Simulation::stats() const { return world_->stats(); }
Status Simulation::status() const { return world_->status(); }
const std::string& Simulation::diagnostic() const { return world_->diagnostic(); }
Motion Simulation::motion(int ball) const { return world_->motion(ball); }
Energy Simulation::energy() const { return world_->energy(); }
Vec3 Simulation::momentum() const { return world_->momentum(); }
std::vector<Contact> Simulation::contacts() const { return world_->contacts(); }
bool Simulation::at_rest() const { return world_->at_rest(); }
void Simulation::set_observer(std::function<void(const StepView&)> observer) { world_->set_observer(std::move(observer)); }
std::vector<std::vector<int>> Simulation::island_balls() const { return world_->island_balls(); }

}  // namespace shotlab
