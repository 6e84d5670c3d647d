// Finding events. After every accepted step the detector compares what holds at the step's end with
// what held at its start (contacts, motion state, in play) and locates each change on the step's dense output (a depth
// or height crossing by a bracketing root finder, the rest by bisection), so an event's time does not depend on where
// the step happened to end.
#pragma once
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "contacts.hpp"
#include "shotlab/event.hpp"
#include "hermite.hpp"
#include "shotlab/model.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

// Motion state of ball i in state vector x: judged relative to its supporting collider (the touching collider
// whose normal points most upwards) with the model's rest_speed threshold on tangential speed and slip. `margin`, when
// given, gets how far x is from changing the answer: the least distance of a quantity that decided it from its
// threshold (m for the support's gap, m/s for speeds; at most 1), zero where the answer changes and continuous along
// a path except where the support passes from one collider to another.
Motion classify(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                double* margin = nullptr);

// The event kind of a ball's change of motion state (shotlab/event.hpp): "rolling", "stopped", "landed", ...
const char* transition_kind(Motion from, Motion to);

// A ball that leaves play during a step (fell through a pocket or off the table).
struct Exit {
  int ball;
  double time;
};

// How closely a friction switch is located (first_law_change): a switch found that close to a trial's end is where
// the trial was cut to end.
inline double switch_resolution(double step) { return std::max(kTimeResolution, kSwitchResolution * step); }

// The share of a step within which method m crosses a friction term's band edge rather than ending the step there
// (band_edges_only): kEarlyShare for the Runge-Kutta pairs, whose stages see the kink's second-derivative jump at eps h
// as an error of order eps^2 h^3; 0 for Bulirsch-Stoer, whose extrapolation assumes a smooth right-hand side, and for
// Rosenbrock 4, whose Jacobian does.
inline double band_edge_share(Method m) {
  return m == Method::CashKarp54 || m == Method::DormandPrince5 ? kEarlyShare : 0.0;
}

class EventDetector {
 public:
  EventDetector(const Model& model, const ModelIndex& index) : model_(model), index_(index) {}
  // Snapshot of what holds in `state` (call at the start and after any discontinuity); the contacts begun at zero
  // depth before it that still touch stay on.
  void reset(const State& state);
  // `record`: the contacts as the right-hand side recorded them at an integrated step's end (Dynamics::recorded,
  // sorted by key), which with `kept` (the contacts the step kept apart, the pairs it looked at) is what scan and
  // first_contact_change compare against the snapshot, bar the beds of balls in a regime, instead of a broad phase of
  // their own (in a breaking rack, a twentieth of the run). Without a record (a closed-form step, a fixed-step method:
  // nullptr), or where a ball moved further than the step's pairs allow for, they look for themselves.
  void scan(const StepSpan& span, const State& state, const StepContacts& kept,
            const std::vector<ContactRecord>* record, std::vector<Event>& events, std::vector<Exit>& exits);
  // Earliest times in the span at which a contact begins and at which one ends (where the force law has a kink);
  // +inf when none. `start`: the contacts at the span's start (sorted by key), whose released ones end with no kink.
  struct Changes {
    double begin, end;
  };
  Changes first_contact_change(const StepSpan& span, const State& state, const StepContacts& kept,
                               const std::vector<ContactRecord>* record,
                               const std::vector<ContactRecord>* start = nullptr);
  // Earliest time in the span at which one of the `separated` contacts touches (depth > 0), located to
  // kOnsetResolution; +inf when none. `which`, when given, gets that contact.
  double first_touch(const StepSpan& span, const std::vector<ContactKey>& separated, ContactKey* which = nullptr);
  // s: how long the contact `key`, separated at the end of `span` by less than kTouch, takes to touch at its closing
  // speed there; 0 when it touches already; +inf when it is not closing, is kTouch or more apart (the next step leaves
  // it out and finds its onset) or cannot touch the collider at all.
  double time_to_touch(const StepSpan& span, const ContactKey& key) const;
  // The earliest time in the span at which a contact that pushed at its start stops pushing (its normal force reaches
  // zero, where the clamp cuts in, or it ends; not where an unclamped one still touches at the end and its pull since
  // cannot matter, pull_matters) or one that pushes at both ends switches its friction's law
  // (friction_switched: a term enters or leaves its smoothing band, or is turned around through it), as `release` or
  // `friction` by its kind; +inf for either kind where it is not the earliest (a contact that has not changed by then
  // is not located) or there is none. Found by comparing the right-hand side's records at the span's two ends
  // (Dynamics::recorded, both sorted by key), located on the span.
  // `next`: the earliest such change of another contact after it, located the same way (+inf when none): where the
  // step after a cut there may end (Island::integrate), the trial's dense output seen past the cut.
  struct LawChanges {
    double release, friction, next;  // s
  };
  LawChanges first_law_change(const StepSpan& span, const std::vector<ContactRecord>& start,
                              const std::vector<ContactRecord>& end) const;

 private:
  using Key = ContactKey;
  static bool released_at_start(const Key& k, const std::vector<ContactRecord>* start);
  // The contacts deeper than kTouch at x, sorted: by a broad phase, or from the record at x.
  void collect(const State& state, const double* x, std::vector<Key>& keys);
  void collect(const State& state, const StepSpan& span, const StepContacts& kept,
               const std::vector<ContactRecord>& record, std::vector<Key>& keys);
  // Appends ball i's contacts with colliders deeper than kTouch at x.
  void collider_contacts(int i, const double* x, std::vector<Key>& keys) const;
  // The contacts at the span's end (now_), and which of them began (begun_) or ended (ended_) since the snapshot.
  void changes(const State& state, const StepSpan& span, const StepContacts& kept,
               const std::vector<ContactRecord>* record);
  double depth(const Key& key, const double* x) const;
  // The contact's force at x by the plain law, seen from key.first (none where it does not touch).
  ContactForce force_at(const Key& key, const double* x) const;
  bool touches(const Key& key, const double* x) const;   // depth > 0
  // Whether a friction switch of contact `key` between laws a and b, over a step of h seconds, can matter (events.cpp).
  bool moves(const Key& key, const FrictionState& a, const FrictionState& b, double h) const;
  // first_law_change's stages (events.cpp): the changes found so far, a contact's release, its friction's switch.
  struct LawSearch;
  void release_change(const StepSpan& span, const Key& key, const ContactRecord* end, LawSearch& so_far) const;
  void friction_change(const StepSpan& span, const ContactRecord& start, LawSearch& so_far) const;
  // Whether the pull of a contact released at `from` inside the span can matter by its end (events.cpp).
  bool pull_matters(const StepSpan& span, const Key& key, double from) const;
  double mobility(const Key& key) const;  // 1/kg: the slip mobility of the key's balls, summed
  // N: the contact's unclamped normal force at x, negated; 1 where it does not touch. Released where it is >= 0: a
  // smooth quantity while the contact lasts, whose root a root finder closes in on.
  double pull(const Key& key, const double* x) const;
  // When the depth of contact `key` passes `level` (m) inside the span, going deeper (begins) or shallower, to
  // `resolution` (s): the span's end is past it, its start is not.
  double crossing(const StepSpan& span, const Key& key, bool begins, double resolution, double level = kTouch) const;
  std::string body_name(int other) const;
  // The key's balls (one, or two for a ball pair) at time t of the span, in scratch_; the other balls' numbers there
  // are stale. What every root finder's and bisection's test looks at.
  const double* balls_at(const StepSpan& span, double t, const Key& key) const;

  const Model& model_;
  const ModelIndex& index_;
  BroadPhase broad_;
  std::vector<Key> contacts_;
  std::vector<Key> now_, begun_, ended_;  // changes()' results, kept to spare allocations per step
  State memo_;                 // the flags and state of the last collect (its time unused) ...
  std::vector<Key> memo_keys_;  // ... and what it found
  std::vector<Motion> motion_;
  mutable StateVector scratch_;
};

}  // namespace shotlab
