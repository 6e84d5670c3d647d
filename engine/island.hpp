// An island: a group of balls integrated together as one ODE system, on its own clock and with its own step size
// (docs/model.md#islands). The simulation (simulation.hpp) splits a scene into islands, each of which
// cannot touch anything outside it before its deadline (partition.hpp), so a collision on one side of the table does
// not force small steps on the other, and a ball that sleeps is in no island and costs nothing.
//
// An island is a small scene of its own: a sub-model holding its balls (the awake ones and the sleepers they may
// reach) and every collider. The right-hand side, the event detector, the regimes and the step cap are the
// whole-scene code run on that sub-model, so each costs what the island's balls cost, whatever else is on the table.
#pragma once
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamics.hpp"
#include "events.hpp"
#include "free_path.hpp"
#include "hermite.hpp"
#include "shotlab/stats.hpp"
#include "shotlab/step_view.hpp"
#include "shotlab/model.hpp"
#include "regimes.hpp"
#include "shotlab/state.hpp"
#include "stepper.hpp"

namespace shotlab {

class Island {
 public:
  // The balls `balls` (indices into `world`, ascending) as they are in `world_state`, from its time on. `first_step`
  // (s) is the adaptive methods' first trial step; `energy_bound` (J) bounds what any of its balls can ever gain
  // (partition.hpp: an island touches nothing else, so its energy cannot grow). `onset_factor`: the world's
  // onset_factor (stepper.hpp), worked out once for all islands.
  Island(const Model& world, const ModelIndex& world_index, const State& world_state, std::vector<int> balls,
         double first_step, double energy_bound, double onset_factor);
  Island(const Island&) = delete;
  Island& operator=(const Island&) = delete;

  // One accepted step that ends at or before `limit` (s). Returns false when the island stopped: status() and
  // diagnostic() say why, and the island stays at its last good point.
  bool step(double limit);

  double time() const { return span_.t1; }
  // s: nothing outside the island can touch it before this time; the simulation steps it no further, then looks at
  // it again (and may lower it whenever another island changes).
  double deadline() const { return deadline_; }
  void set_deadline(double t) { deadline_ = t; }
  double energy_bound() const { return energy_bound_; }
  long call_steps() const { return call_steps_; }  // accepted steps since start_call()
  void start_call() { call_steps_ = 0; }
  const std::vector<int>& balls() const { return balls_; }  // world indices, ascending
  const Model& model() const { return model_; }              // the sub-model: the island's balls, every collider
  const State& state() const { return integ_; }              // the sub-state at time()
  const StepSpan& span() const { return span_; }             // the last accepted step, on the sub-state
  StepView view() const { return {span_.t0, span_.t1, balls_, model_, integ_, start_, stats_, span_}; }
  const Stats& stats() const { return stats_; }
  double next_step() const { return dt_next_; }             // s, what the next step will try
  Status status() const { return status_; }
  const std::string& diagnostic() const { return diagnostic_; }
  std::string describe_balls() const { return describe_balls(span_.x1); }

  // The regime flags at time t in [span().t0, time()]: as of the last step's start for t < time() (a regime changes at
  // a step's end), else as of time().
  const State& flags_at(double t) const { return t < span_.t1 ? start_ : integ_; }
  // The free path (regimes.hpp) of a single-ball island at time t in [span().t0, time()], followed for `horizon`
  // seconds at most; none for an island of several balls or a ball in the full model.
  std::optional<FreePath> free_path(double t, double horizon);

  // Writes the island's balls into a world state: their state at time t in [span().t0, time()], their regime flags
  // as of the last step's start for t < time() (a regime changes at a step's end), else as of time().
  void write(double t, State& world);
  // The island's state vector at time t in [span().t0, time()].
  void state_at(double t, StateVector& x) const { span_.interpolate(t, x); }
  // Undoes the last step and steps again to end exactly at t in [span().t0, time()]: the state at t then comes from
  // the integrator rather than from the step's interpolant, whose error (O(h^4) on a long step) islands formed at t
  // would inherit. Events found again that were handed over before are dropped. Returns false if a step failed.
  bool rewind(double t);
  // J: the total energy of the island's balls and contacts at time() (sleepers included), worked out once a step,
  // and at the island's start. An island touches nothing outside it, so the scene's energy changes by what its
  // islands' energies change.
  double energy();
  double energy_ref() const { return energy_ref_; }
  // Hands over the events located so far at or before t, in time order.
  void take_events(double t, std::vector<Event>& out);

 private:
  // One integrated step's trials (step_control.cpp).
  struct Trials {
    double tried = 0;                 // s: the last trial's length
    double passed = 0;                // s: the first trial the error control accepted
    int retries = 0;                  // redos to end at a change
    bool at_onset = false;            // the step was cut where a contact begins
    bool plain = false;               // redone with the plain law after kMaxRedos
    std::optional<ContactKey> aimed;  // the contact left out of the step where it was cut to end (first_touch)
  };

  // The stages of step(), in order (island.cpp).
  double plan(double limit, bool& constant);
  void freeze_laws();
  double closed_form_to(double t);
  bool finite_or_stop(double t);
  void commit(double t);
  void settle(double t, bool recorded);
  // The step's end (trial_.x1, f1 from trial_.x0, f0 at trial_.t0): by the error-controlled stepper, trying dt first
  // (`limit`: where the step ends when dt was cut to reach it exactly, else NaN; t: the end's time; false when the
  // step failed), or in closed form to t1.
  bool integrate(double dt, double limit, double& t);
  void closed_form_step(double t1);
  // Step control (step_control.cpp).
  double onset_step(double tolerance);  // s: where an onset's own error reaches `tolerance` (StepContacts::onset)
  void load_start_record(bool adaptive);
  bool cut_at_change(Trials& tr, double t, double& dt);
  bool go_on_to_touch(Trials& tr, double& dt);
  void size_next_step(double dt, double wanted, bool capped, bool from_onset, const Trials& tr, bool rejected);
  void restart();  // after the system changed (a ball left play): fresh derivative, stepper history, snapshot
  void stop(Status why, std::string message);
  std::string describe_balls(const StateVector& x) const;

  std::vector<int> balls_;
  Model model_;
  ModelIndex index_;  // of model_, shared by the dynamics, the detector, the regimes and the step cap
  State integ_;  // integrator state at span_.t1 (its in_play is what the right-hand side sees)
  State start_;  // the regime flags at span_.t0 (its x unused)
  Dynamics dynamics_;
  double onset_growth_;  // onset_factor^(1/5): how much longer the step after an onset may be (integrate)
  std::unique_ptr<Stepper> stepper_;
  EventDetector detector_;
  Regimes regimes_;
  BroadPhase cap_broad_;  // broad phase of the step cap
  StepContacts plan_;       // the step's contact lists as the cap finds them (then the last step's, swapped out)
  StateVector f_start_;     // f at the step's start
  std::vector<ContactRecord> start_record_, end_record_;  // the contacts there and at a trial's end (Dynamics::recorded),
                                                         // sorted by key
  bool end_record_is_start_ = false;  // end_record_ is the record at the step's start (the last step's accepted end)
  StepSpan trial_;          // the step's trial (buffers reused from step to step)
  std::vector<Swing> continuing_;  // the last step's swings, their phases at its end (time_to_band_edge)
  std::vector<BedBounce> bouncing_;  // the last step's bounces, moved on to its end (time_to_band_edge)
  StepSpan span_;
  double dt_next_;
  // s: where the next step ends, a change that the last step's trials found past where it was cut (integrate); +inf
  double aim_ = std::numeric_limits<double>::infinity();
  double onset_exponent_ = 0, onset_coefficient_ = 0;  // onset_error_coefficient of the last onset's exponent
  double deadline_ = 0;
  double energy_bound_;
  long call_steps_ = 0;
  std::vector<Event> events_;  // located, not yet handed over
  double handed_until_ = -std::numeric_limits<double>::infinity();  // s: events up to here were handed over
  Stats stats_;
  double energy_ref_;
  Status status_ = Status::Ok;
  std::string diagnostic_;
  StateVector scratch_;
  State energy_state_;  // scratch for energy()
  double energy_ = 0;   // J: energy() as of the step count energy_steps_
  long energy_steps_ = -1;
};

}  // namespace shotlab
