// Regimes: what part of the model a ball needs right now, decided at step boundaries (docs/model.md#regimes).
//  - free: the full model;
//  - sliding: alone on the bed and settled onto it: held at its static sink, the bed's friction at its weight, no
//    stiff vertical contact mode to integrate;
//  - rolling: alone on the bed with no slip: closed-form rolling instead of the stiff smoothed friction;
//  - flight: held by no rod and touching nothing: constant acceleration (gravity), in closed form;
//  - asleep: a group of touching balls at rest for sleep_time is frozen exactly until a moving ball touches it.
// Friction tails inside their bands follow band_tail.hpp, a ball alone on its rod swing.hpp. A ball leaves a regime
// when anything but its bed comes within contact_margin or its support is no longer the flat bed; contact onsets end
// steps, so regime changes happen at the instant of contact.
#pragma once
#include <optional>
#include <vector>

#include "contacts.hpp"
#include "shotlab/model.hpp"
#include "band_tail.hpp"
#include "bounce.hpp"
#include "shotlab/state.hpp"
#include "swing.hpp"

namespace shotlab {


class Regimes {
 public:
  Regimes(const Model& model, const ModelIndex& index);
  // After an accepted step of dt seconds ending at state x: updates state.asleep, state.rolling_on, state.sliding_on
  // and state.still_for, zeroes the velocities of new sleepers, snaps new rollers onto the rolling constraint and new
  // sliders onto the bed.
  // Returns true when any ball changed regime: the system changed and the integrator must restart.
  bool update(State& state, StateVector& x, double dt);

 private:
  // Sleep (sleep.cpp): whether ball i rests; ball i held still off any support, pressed by nothing (under the anchor
  // of its one rod, a Newton's cradle's resting balls, or in free space without gravity); the sleep and wake pass.
  bool at_rest(const State& state, const StateVector& x, int i) const;
  bool held_still(const StateVector& x, int i) const;
  // The force still on a ball at zero speed (its contacts' elastic forces and gravity) would move it past rest_speed
  // within sleep_time: a contact pre-loaded beyond the ball's weight (a ball started inside the bed, a cushion or
  // another ball) pushes apart instead of falling asleep.
  bool unbalanced(const StateVector& x, int i) const;
  double hop(int i, int bed, double vn, double offset) const;  // m/s, see regimes.cpp
  bool update_sleep(State& state, StateVector& x, double dt);
  bool wake_touched(State& state, const StateVector& x);  // update_sleep's stages (sleep.cpp)
  bool sleep_rested(State& state, StateVector& x);
  bool frozen_touch(const StateVector& x, int i, int j) const;  // closer than kTouch
  bool slip_below(const StateVector& x, int i, const Vec3& n, double limit) const;  // tangential slip at the bed
  bool update_rolling(State& state, StateVector& x);
  bool update_sliding(State& state, StateVector& x);
  bool settle_rolling(StateVector& x, int i, const Vec3& n) const;  // stops a rolling ball at the end of its tail
  // The bed collider (its unit normal and the centre height of a ball resting on it in `normal`, `height`) when
  // ball i touches exactly one flat bed and nothing else within contact_margin; -1 otherwise.
  int only_on_bed(const StateVector& x, int i, Vec3& normal, double& height) const;
  double sink(int i, int plane) const;  // m: ball i's static sink into plane-like collider `plane`

  const Model& model_;
  const ModelIndex& index_;
  BroadPhase broad_;
  std::vector<std::vector<int>> touching_;  // neighbours (frozen-touching included), rebuilt each update
  std::vector<uint8_t> resting_, seen_;  // update_sleep's work lists, kept to spare an allocation per step
  std::vector<int> stack_, group_;
  std::vector<double> sink_;  // m: each ball's static sink into each plane-like collider (ball-major, index_.plane_like)
  struct Support {
    int collider = -1;  // only_on_bed's answer, with its normal and height
    Vec3 normal{0.0};
    double height = 0;
  };
  std::vector<Support> bed_;  // each ball's, worked out once an update
};

// m/s: the slip under which a ball enters the rolling regime (kEntrySlip, numerics.hpp).
double entry_slip(const Model& model);

// m: how deep ball b sinks into a bed of material m under its own weight (C d^e = m g).
double static_sink(const BallSpec& b, const ContactMaterial& m, double g);
// The flat, horizontal bed a ball can roll on in closed form: a plane (bounded or not) whose unit normal (from the
// contact index, 0 for other shapes) is along -gravity; `point` is a point of it.
bool flat_bed(const Collider& c, const Vec3& normal, const Vec3& gravity, Vec3& point);
// The one collider within contact_margin of a ball (centre p, radius r) when that is a flat bed that holds it (not its
// rim over a pocket's hole): its index, with a point of it and the ball's penetration into it (m); -1 when there is
// none or something else is that close. Other balls and rods are the caller's to rule out.
int only_bed_near(const Model& model, const ModelIndex& index, const Vec3& p, double r, Vec3& point, double& depth);
// m/s: a ball's vertical motion on a bed of material m (normal speed vn, height offset from its static sink `sink`)
// as the speed of its amplitude in the linearised bed contact (stiffness e m g / sink, so omega^2 = e g / sink).
double bed_hop(const ContactMaterial& m, double g, double sink, double vn, double offset);
// Whether ball i (its 9 numbers at b), alone on the flat bed `bed` (unit normal n) with normal speed vn (m/s) and its
// centre `offset` m above its static sink `sink`, has settled enough to enter the sliding regime (update_sliding).
bool settles_on_bed(const Model& model, const ModelIndex& index, const double* b, int i, int bed, const Vec3& n,
                    double vn, double offset, double sink);

// s: the earliest time at which a ball in the rolling or sliding regime reaches the edge of a friction term's smoothing
// band (fricstep's clamp at k s = 1: a kink in the right-hand side); +inf when none does. Outside the bands the
// regimes' motion is polynomial in time (constant forces), so the time is exact. A step that ends there crosses no
// kink: an embedded error estimate misjudges a step across one, and the step is rejected over and over as the kink
// comes closer.
// With `constant`, also says whether the right-hand side is constant until then: every ball in play asleep, or in the
// rolling or sliding regime with each of its friction terms outside its band (or at a zero that holds: no speed, no
// spin about the normal). The island may then step in closed form (island.cpp). With `tails`, a spin about the
// normal, a rolling speed or (where its closed form holds) a sliding ball's slip inside its band does not count
// against that: it is listed there instead, to be followed in closed form (band_tail.hpp), and a tail's end (the
// stop cut, the rolling entry) counts as an edge. With `swings`, neither does a ball in the full model that swings
// alone on its rod (swing_of): it is listed there, to follow the pendulum's closed form (`continuing`: the swings of
// the step that ended at x, their phases moved on to its end); nor one that flies (Options::flight_regime: held by no
// rod, nothing within contact_margin), whose right-hand side is gravity alone. With `bounces`, neither does a ball that
// bounces on the bed alone (bed_bounce_of; going on with the last step's where it can, else followed anew for at most
// their horizon): it is listed there, its end an edge.
double time_to_band_edge(const Model& model, const State& state, const ModelIndex& index, const double* x,
                         bool* constant = nullptr, std::vector<BandTail>* tails = nullptr,
                         std::vector<Swing>* swings = nullptr, const std::vector<Swing>* continuing = nullptr,
                         BounceWork* bounces = nullptr);

// s: how long ball i, rolling or sliding with the regime's acceleration `a` (m/s^2), keeps it constant and its
// velocity free of jumps: until its speed (rolling) or its slip (sliding) falls to its friction band's edge, where its
// law turns, or to the stop cut's speed or the rolling entry's slip, where a regime snaps it, and (with sleep on) no
// later than its speed may fall to rest_speed, where it may fall asleep; 0 from there on, or where the bed's friction
// depends on the slip. +inf rolling without rolling resistance or sleep.
double steady_for(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                  const Vec3& a);

}  // namespace shotlab
