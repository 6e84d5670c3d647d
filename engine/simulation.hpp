// The stepping loop (MODEL.md 5.2.4): advance(dt) moves the clock to exactly t + dt. The integrator steps on its
// own schedule, independent of how the caller slices time: it steps past the target and the state at the target
// comes from the step's dense output. Frames of 1/30 s, 1/240 s or one call give bit-identical results.
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "diagnostics.hpp"
#include "dynamics.hpp"
#include "events.hpp"
#include "hermite.hpp"
#include "regimes.hpp"
#include "model.hpp"
#include "state.hpp"
#include "stepper.hpp"

namespace shotlab {

enum class Status {
  Ok,
  StepLimit,     // max_steps_per_call steps in one advance() without reaching the target: the clock stops short
  NonFinite,     // the state became NaN or infinite: the simulation stops at the last finite step
  StepTooSmall,  // the error control shrank the step below 1e-14 s
  Unstable,      // the total energy grew by more than the initial kinetic and elastic energy plus 1 J: a passive
                 // system cannot gain energy, so the integration has gone unstable (a fixed step too large for the
                 // stiffness) while staying finite
};
const char* status_name(Status s);

struct Stats {
  long steps = 0;           // accepted steps
  long rejected_steps = 0;  // attempts the error control threw away
  long redone_steps = 0;    // accepted attempts redone to end where a contact begins or ends
  long rhs_evaluations = 0; // calls of the right-hand side (Jacobian columns included)
  double wall_seconds = 0;  // spent inside advance()
  double last_step = 0;     // s, the most recent accepted step
};

class Simulation {
 public:
  Simulation(Model model, State initial);
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // Advance the clock by dt >= 0 s (a negative dt throws std::invalid_argument). Returns Ok, or why it stopped (then status() stays so and diagnostic() says
  // where and which balls; further calls do nothing).
  Status advance(double dt);

  double time() const { return state_.time; }
  const State& state() const { return state_; }
  const Model& model() const { return model_; }
  const std::vector<Event>& events() const { return events_; }
  const Stats& stats() const { return stats_; }
  Status status() const { return status_; }
  const std::string& diagnostic() const { return diagnostic_; }

  Motion motion(int ball) const { return classify(model_, cap_cache_, state_, state_.x.data(), ball); }
  Energy energy() const { return shotlab::energy(model_, state_); }
  Vec3 momentum() const { return shotlab::momentum(model_, state_); }
  std::vector<Contact> contacts() const { return shotlab::contacts(model_, state_); }
  // True when every ball in play is stationary (or out of play): nothing will move again.
  bool at_rest() const;

  // Called after every accepted step with its span (odeint's observer): step-size plots, per-contact counts.
  void set_observer(std::function<void(const StepSpan&)> observer) { observer_ = std::move(observer); }

 private:
  bool step();
  void restart();  // after the system changed (a ball left play): fresh derivative, stepper history, snapshot
  void stop(Status why, std::string message);
  std::string describe_balls(const StateVector& x) const;

  Model model_;
  State integ_;  // integrator state at span_.t1 (its in_play is what the right-hand side sees)
  State state_;  // the state at the caller's clock, interpolated
  Dynamics dynamics_;
  std::unique_ptr<Stepper> stepper_;
  EventDetector detector_;
  Regimes regimes_;
  ContactCache cap_cache_;  // broad phase of the step cap
  StepSpan span_;
  double dt_next_;
  std::vector<Event> events_;
  Stats stats_;
  Status status_ = Status::Ok;
  std::string diagnostic_;
  std::function<void(const StepSpan&)> observer_;
  double energy_start_, energy_scale_;  // J: total at t = 0, and what it may grow by before the run is Unstable
  // J: the energy of sleepers and of the beds under rolling balls, constant between regime changes (taken at each
  // restart), so that the energy check after every advance() costs O(awake balls), not O(balls).
  double energy_frozen_ = 0;
};

}  // namespace shotlab
