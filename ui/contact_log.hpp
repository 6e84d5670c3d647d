// Every contact of a shot other than a ball resting on the bed, with its normal force and depth over time: for the
// collision plot (teachers) and the per-contact inspector (developers). The events name each contact and its
// begin and end; the force history comes from simulating the shot again and evaluating the contact on every step's
// dense output while it lasts, so even a 0.2 ms collision is drawn as a smooth curve of a hundred points, at the
// cost of one more run of the shot (on a worker thread, following the shot as it plays).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "shotlab/event.hpp"
#include "shotlab/scene.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

struct ContactTrace {
  std::string a, b;              // ball id; ball id or collider name ("cushion-top-left", "jaw-...")
  bool ball_ball = false;
  double begin = 0, end = -1;    // s; end < 0: still touching where the log ends
  std::vector<double> time;      // s
  std::vector<double> force;     // N, normal
  std::vector<double> depth;     // m, penetration
  std::string label() const { return a + " - " + b; }
  double peak_force() const;
  double max_depth() const;
};

struct ContactLog {
  double until = 0;      // s: the traces cover the shot up to here
  size_t events = 0;     // how many of the shot's events it was built from
  std::vector<ContactTrace> contacts;  // in order of their begin
};

// The contacts named by `events` other than the bed's, their begin and end (end < 0: not ended by the last event),
// untraced; a ball that left play ends its contacts there.
std::vector<ContactTrace> contact_spans(const std::vector<Event>& events, const Model& model);

// Traces a shot's contacts as it goes: each extend() runs its own simulation of the shot on from where the last one
// stopped, keeping the traces so far, so that a log followed while the shot plays costs one more run of the shot in
// all. A contact that begins where a call stops may miss the sample at its very begin (force zero there).
class ContactTracer {
 public:
  explicit ContactTracer(const Scene& start);
  ~ContactTracer();
  // The log up to `until` s, from the shot's events so far (every contact that begins before `until`).
  const ContactLog& extend(const std::vector<Event>& events, double until);
  const ContactLog& log() const { return log_; }

 private:
  std::unique_ptr<Simulation> sim_;
  ContactLog log_;
};

// The contacts named by `events` (a shot of `start`), traced up to `until` s: one extend() of a new tracer.
ContactLog trace_contacts(const Scene& start, const std::vector<Event>& events, double until);

}  // namespace shotlab
