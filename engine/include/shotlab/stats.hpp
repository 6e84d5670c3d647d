// How a simulation went: its status (why it stopped, if it did) and its counts.
#pragma once

namespace shotlab {

enum class Status {
  Ok,
  StepLimit,     // max_steps_per_call steps in one counting window (Simulation::advance) short of the target: the clock stops
  NonFinite,     // the state became NaN or infinite: the simulation stops at the last finite step
  StepTooSmall,  // the error control shrank the step below 1e-14 s
  Unstable,      // the total energy grew by more than the initial kinetic and elastic energy plus 1 J: a passive
                 // system cannot gain energy, so the integration has gone unstable (a fixed step too large for the
                 // stiffness) while staying finite
};
const char* status_name(Status s);

struct Stats {
  long steps = 0;           // accepted steps (of all islands); on the rigid model, the events it handled
  long rejected_steps = 0;  // attempts the error control threw away
  long redone_steps = 0;    // accepted attempts redone to end where a contact begins or ends
  long rhs_evaluations = 0; // calls of the right-hand side (Jacobian columns included)
  double wall_seconds = 0;  // spent inside advance()
  double last_step = 0;     // s, the most recent accepted step
  Stats& operator+=(const Stats& o);  // adds the counts
};

}  // namespace shotlab
