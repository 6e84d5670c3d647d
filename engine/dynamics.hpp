// THE right-hand side of the ODE (docs/model.md#motion): given the state, the time derivative of every ball's
// position, velocity and angular velocity. Force sources, each in one place:
//   gravity ............ here (accumulate_gravity)
//   contacts ........... contact_force_impl.hpp (one law for ball-ball, cloth, cushions, any collider),
//                        found by contacts.hpp
//   rods ............... here (apply_rods): constraint forces, computed last because they cancel the others
//   rolling regime ..... regimes.cpp (rolling_derivative): closed-form rolling on the bed, replacing the above for
//                        a ball that rolls and touches nothing else
//   sliding regime ..... regimes.cpp (sliding_derivative): the bed's friction at the static sink, for a ball that
//                        slides on the bed, settled onto it, and touches nothing else
#pragma once
#include <vector>

#include "contacts.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

class Dynamics {
 public:
  // The references must outlive the Dynamics; `state` supplies which balls are in play.
  Dynamics(const Model& model, const ModelIndex& index, const State& state);

  // odeint's system signature: dxdt = f(x, t).
  void operator()(const StateVector& x, StateVector& dxdt, double t);

  long evaluations() const { return evaluations_; }
  // The plan of the step about to be taken: how it treats its changing contacts (contacts.hpp, StepContacts; empty
  // lists: the plain law), handed to every contact pass until the next. Swapped in, so that the caller's lists keep
  // their storage and hold the last step's afterwards.
  void swap_plan(StepContacts& plan) {
    std::swap(plan_, plan);
    ++plan_swaps_;
  }
  long plan_swaps() const { return plan_swaps_; }  // how often the step's contact laws were swapped (invariant checks)
  const StepContacts& plan() const { return plan_; }
  // The balls' flags changed since the step's lists were made (one woke, one left play): the right-hand side sweeps
  // for touching pairs and probes every collider again until the next step's lists come.
  void sweep_again() { plan_.near_known = plan_.colliders_known = false; }
  // What each contact's friction did in the last evaluation made while recording (on unless a stepper turned it off
  // for the inner stages of its step, stepper.hpp): the island compares it at a step's two ends to find where a
  // friction term switched its law or a contact let go (EventDetector::first_law_change). In the order evaluated.
  void set_recording(bool on) { recording_ = on; }
  const std::vector<ContactRecord>& recorded() const { return recorded_; }

 private:
  // Every contact's force and torque into force_ and torque_; with Record, also into recorded_.
  template <bool Record>
  void add_contacts(const StateVector& x);
  void apply_rods(const StateVector& x, StateVector& dxdt) const;

  const Model& model_;
  const ModelIndex& index_;
  const State& state_;
  BroadPhase broad_;
  StepContacts plan_;
  std::vector<Vec3> force_, torque_;
  long evaluations_ = 0;
  long plan_swaps_ = 0;
  bool recording_ = true;
  std::vector<ContactRecord> recorded_;
};

// Right-hand sides of a ball in the rolling and the sliding regime (regimes.hpp), written into dxdt.
void rolling_derivative(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                        double* dxdt);
void sliding_derivative(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                        double* dxdt);

}  // namespace shotlab
