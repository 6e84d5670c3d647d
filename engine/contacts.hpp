// Contact detection: which bodies touch, and the force each contact carries. The right-hand side, the diagnostics
// and the event detector all see contacts through for_each_contact, so there is one definition of "touching".
#pragma once
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "bounce.hpp"
#include "contact_force.hpp"
#include "shotlab/diagnostics.hpp"
#include "shotlab/model.hpp"
#include "model_index.hpp"
#include "numerics.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

// A contact's bodies: (ball, other ball) with ball < other, or (ball, -1 - collider index).
using ContactKey = std::pair<int, int>;

// A step's plan for its contacts (made by the step cap, step_control.cpp): each contact keeps the law it had at the
// step's start, so that no step straddles an onset's jump or the clamp's kink; the island ends the step where a law
// would change (docs/model.md#step-control). Keys sorted.
struct StepContacts {
  std::vector<ContactKey> separated;  // separated by kTouch or more at the start: left out of the step
  std::vector<ContactKey> pushing;    // pushing at the start, but near the clamp: not clamped in the step
  // With near_known: every other pair of balls that the step's cap (time_to_possible_contact) found close enough to
  // touch within the step, as (left, right) in its sweep. No other pair can touch in the step, so the right-hand side
  // checks these instead of sweeping again on each of its six calls a step.
  std::vector<ContactKey> near;
  bool near_known = false;
  // m, with near_known: the cap's sweep found every pair of balls whose extents came within this of each other at the
  // step's start (the pairs in near or separated). No other pair can touch unless its balls moved more than this
  // between them (EventDetector::collect: balls pushed harder than the cap's acceleration bound).
  double reach = 0;
  // With colliders_known: ball i's colliders within its reach over the step (near_colliders at the cap's travel, in
  // its order) are colliders[collider_from[i]] up to colliders[collider_from[i + 1]]. The stages of a step probe only
  // these (for_each_contact); the evaluation that records, at a trial's end, probes them all, so that a ball pushed
  // past its reach still shows the contact it ran into to the event detector.
  std::vector<int> colliders, collider_from;
  bool colliders_known = false;
  // A contact begins at the step's start: within kTouch of zero depth and closing. Its force grows as depth^e (Hertz:
  // e = 1.5) from there, which the step's error estimate understates (stepper.hpp, onset_underestimate).
  bool onset = false;
  // Of the contacts that begin: the largest C v^e / m (C, e: the material's stiffness and exponent, v the closing
  // speed, m the lighter ball's mass), the coefficient of the velocity change C v^e t^(e+1) / ((e+1) m) at the onset
  // that no polynomial follows, and that contact's e and v.
  double onset_strength = 0, onset_exponent = 1.5, onset_speed = 0;
};
inline const StepContacts kNoPlan{};  // no step's plan: every contact with its plain law, found by a sweep

// One touching contact as an evaluation of the right-hand side saw it (Dynamics::recorded), seen from key.first: what
// the event detector compares at a step's two ends (EventDetector::first_law_change).
// Of two balls of different radii, the spin term's band is taken at the radius of the ball the contact pass evaluated
// it from (the sweep's order) and the detector's bisection at key.first's: a switch of that term may then be missed or
// found where there is none, never a force changed. Every preset's balls have one radius.
struct ContactRecord {
  ContactKey key{0, 0};
  double depth = 0;   // m
  double normal = 0;  // N, the normal force (negative where the step keeps the contact's law unclamped)
  FrictionState friction;
};

// The broad phase's buffers, kept from call to call so that it allocates nothing: each user of sweep_pairs owns one.
struct BroadPhase {
  std::vector<std::pair<int, int>> pairs;  // overlapping_pairs' answer
  // Awake balls sorted by the left end of their x extent on every call; sleepers sorted once per change of who
  // sleeps (they do not move), so that a thousand resting balls cost a binary search, not a sweep.
  std::vector<int> awake;
  std::vector<int> strip_start, strip_order, strip_fill;  // sweep_strips' buckets (contacts_impl.hpp)
  std::vector<int> sleepers;
  std::vector<double> sleeper_left;  // x - R of each sleeper, ascending
  std::vector<uint8_t> sleep_key;    // in_play and asleep flags the sleeper list was built for
};

// Calls fn(i, j) for every pair of balls in play, at least one of them awake, whose x extents come within `reach`
// (m) of each other (for 64 awake balls or more: whose x and z extents both do); with `sleeping_pairs`, also pairs of
// two sleepers. The candidates of sweep-and-prune along x, in strips along z from 64 awake balls on (sweep_strips):
// O(awake log awake + candidates) when the caller passes the list of awake balls in play (`awake`), plus a pass over
// the balls' flags without it.
template <class Fn>
void sweep_pairs(const Model& model, const ModelIndex& index, const State& state, const double* x, BroadPhase& broad,
                 double reach, bool sleeping_pairs, Fn&& fn, const std::vector<int>* awake = nullptr);

// The sleepers whose x extents come within `reach` of ball i's (i itself excluded).
template <class Fn>
void sleepers_near(const Model& model, const ModelIndex& index, const double* x, const BroadPhase& broad, int i,
                   double reach, Fn&& fn);

// Calls fn(c, pen) for every collider c whose gap to a ball (centre p, radius r) may be under `within` m, with its
// penetration (pen.depth may still be <= -within: the bounds are a box). The colliders' bounds reject most of a
// table's cushions before the exact test is called: every step runs this for every ball in several passes (contact
// onsets, motion states, regimes, step caps), and the calls themselves were a quarter of a break's wall time.
template <class Fn>
void near_colliders(const Model& model, const ModelIndex& index, const Vec3& p, double r, double within, Fn&& fn);

// near_colliders' test of one collider c that it visits: fn(c, pen) where it would call it.
template <class Fn>
void near_collider(const Model& model, const ModelIndex& index, int c, const Vec3& p, double r, double within, Fn&& fn);

// The penetration of a ball (centre p, radius r) into collider c (colliders.hpp, penetration), the way near_colliders
// finds it: over a level floor by one subtraction instead of the shape's test of its extent and its holes.
inline std::optional<Penetration> collider_penetration(const Model& model, const ModelIndex& index, int c, const Vec3& p,
                                                       double r, double within = std::numeric_limits<double>::infinity()) {
  if (index.floor_of[c] >= 0)
    if (const auto on_floor = floor_penetration(index, static_cast<size_t>(index.floor_of[c]), p, r)) return *on_floor;
  return penetration(model.colliders[c].shape, p, r, within);
}

// Ball pairs (at least one awake, or any with `sleeping_pairs`) whose spheres overlap or come closer than `slack` m.
// Into broad.pairs.
void overlapping_pairs(const Model& model, const ModelIndex& index, const State& state, const double* x,
                       BroadPhase& broad, double slack = 0.0, bool sleeping_pairs = false);

// The kinematics of ball i (radius r, velocity v, spin w) against a static collider whose normal (towards the ball's
// centre) is `normal`, penetrated by `depth`.
template <class Normal>
Kinematics<Normal> collider_kinematics(const ModelIndex& index, int i, double r, const Vec3& v, const Vec3& w,
                                       Normal normal, double depth) {
  return {normal, depth, v, v + r * normal_cross(normal, w), normal_component(w, normal), r,
          index.inv_mass[i] + index.inv_inertia_r2[i], index.inv_mass[i], index.inv_inertia_r2[i]};
}

// The force of the contact of ball i (radius r, velocity v, spin w) with collider c, whose material is `mat`, at
// penetration `pen`: through the law's component form where the normal is straight up (the bed). Always inlined, like
// the law itself, so that the 96-byte ContactForce stays in registers instead of going through memory.
[[gnu::always_inline]] inline ContactForce collider_force(const ContactMaterial& mat, const ModelIndex& index, int i,
                                                          double r, const Vec3& v, const Vec3& w, const Penetration& pen,
                                                          const Smoothing& smoothing, bool clamp = true) {
  return pen.normal == kUp ? contact_force(mat, collider_kinematics(index, i, r, v, w, UpNormal{}, pen.depth), smoothing, clamp)
                           : contact_force(mat, collider_kinematics(index, i, r, v, w, pen.normal, pen.depth), smoothing, clamp);
}

// The kinematics of balls i and j (centres d = |p_i - p_j| apart, d > 0 unless they coincide) from i's side: the normal
// from j to i, A's contact point at -R_i n and B's at +R_j n.
inline ContactKinematics pair_kinematics(const Model& model, const ModelIndex& index, const double* x, int i, int j) {
  const double ri = model.balls[i].radius, rj = model.balls[j].radius;
  const Vec3 d = position(x, i) - position(x, j);
  const double dist = glm::length(d);
  const Vec3 nrm = dist > 0 ? d / dist : kUp;
  const Vec3 wi = spin(x, i), wj = spin(x, j);
  const Vec3 vrel = velocity(x, i) - velocity(x, j);
  const Vec3 slip = vrel + ri * glm::cross(nrm, wi) + rj * glm::cross(nrm, wj);
  return {nrm, ri + rj - dist, vrel, slip, glm::dot(wi - wj, nrm), ri,
          index.inv_mass[i] + index.inv_inertia_r2[i] + index.inv_mass[j] + index.inv_inertia_r2[j],
          index.inv_mass[i] + index.inv_mass[j], index.inv_inertia_r2[i] + index.inv_inertia_r2[j]};
}

// Calls fn(const Contact&) for every touching ball-collider and ball-ball pair of balls in play. `x` is the state
// vector (9 numbers a ball), which may differ from state.x (the integrator's trial states). Contacts that no
// ball's dynamics uses (between sleeping balls; the bed under a ball in the rolling or sliding regime, whose support is
// in closed form) are left out unless `with_inactive` (diagnostics want them). `plan`: the step's frozen contact laws
// (StepContacts; none: every contact with its plain law, found by a sweep). `inner_stage`: an evaluation inside a
// step, which probes only the plan's colliders of each ball (StepContacts::colliders).
template <class Fn>
void for_each_contact(const Model& model, const ModelIndex& index, const State& state, const double* x,
                      BroadPhase& broad, const StepContacts* plan, Fn&& fn, bool with_inactive = false,
                      bool inner_stage = false);

// A lower bound on the time before any still-separated pair (ball-ball or ball-collider) could touch, given current
// velocities and an acceleration bound; +inf when nothing can within `horizon` (the step the integrator wants).
// Adaptive steps are capped by it so that no contact, however glancing, falls between two steps
// (docs/model.md#step-cap). Ball pairs use their relative speed, so a cluster moving together is not held back. With
// `step`, also sorts the contacts it looks at into step->separated (every contact that could begin within the
// horizon, none that cannot: the list is searched on every right-hand side) and step->pushing. `flight`: the step
// moves every ball in closed form, so a ball in the full model that no rod holds flies (regimes.hpp), under gravity
// alone until the first onset, and its bound is |g| instead of free_acceleration's. A ball in `bounces` (bounce.hpp)
// takes its bounce's bounds instead and is not held back by its bed, which its bounce follows, but by the bed's holes.
double time_to_possible_contact(const Model& model, const ModelIndex& index, const State& state, const double* x,
                                double horizon, BroadPhase& broad, StepContacts* step = nullptr, bool flight = false,
                                const std::vector<BedBounce>* bounces = nullptr);

// Whether ball i (at x) is farther than contact_margin from every other ball in play and from every collider: no
// contact acts on it (the swing and the flight move such a ball in closed form, regimes.hpp).
bool clear_of_contacts(const Model& model, const ModelIndex& index, const State& state, const double* x, int i);

// m/s^2: a bound on ball i's acceleration while it touches nothing but the bed it rolls or slides on: rolling
// resistance mu_r g when rolling, (mu + mu_r) g when sliding, generously 2 |g| otherwise (a ball in the air, one
// settling onto the bed).
double free_acceleration(const State& state, const ModelIndex& index, int i);

// m/s^2: bounds on a ball's acceleration outside contacts, in all and across (its horizontal part). One number bounds
// both; a ball flying under gravity alone has only gravity's horizontal part across (none unless it is tilted).
struct AccelBound {
  double total, across;
  AccelBound(double a) : total(a), across(a) {}  // implicit: a plain number bounds both
  AccelBound(double total, double across) : total(total), across(across) {}
};

// s: a lower bound on the time before ball i, its acceleration bounded by `a` outside contacts, could come
// contact_margin into a collider other than the bed it rolls, slides or bounces on (`bounce_bed`; as far as a step
// may take it), or that far over a hole's edge in that bed; +inf when nothing can within `horizon`. With `step`,
// lists the ball's contacts in step->separated and step->pushing as time_to_possible_contact does (unsorted), and
// every collider it looked at in step->colliders.
double collider_contact_time(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                             double horizon, AccelBound a, StepContacts* step = nullptr, int bounce_bed = -1);

// s: when two balls whose centres are d0 apart (m, d0 = p_i - p_j) and whose relative velocity is v (m/s) come within
// `reach` (m) of each other on straight paths; +inf when they pass wider than that, 0 when they are that close now.
double straight_line_contact_time(const Vec3& d0, const Vec3& v, double reach);

// s: a lower bound on when two balls come within `reach` (m) of each other while their offset strays from d0 + v t
// by at most a t^2 / 2 (d0, v as above; a: a bound on their relative acceleration, m/s^2); valid up to h (s).
double pair_contact_time(const Vec3& d0, const Vec3& v, double reach, double a, double h);

// The energy of what the integrator moves (with_inactive = false): awake balls in play and the contacts
// for_each_contact evaluates for them, i.e. without sleepers and the bed under a rolling ball, whose energy stays
// constant until a regime changes. With `with_inactive`, the total, as energy(model, state) (diagnostics.cpp).
Energy energy(const Model& model, const ModelIndex& index, const State& state, BroadPhase& broad, bool with_inactive);

}  // namespace shotlab

#include "contacts_impl.hpp"
