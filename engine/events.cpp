#include "events.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>
#include <limits>

namespace shotlab {
namespace {


// First time in (lo, hi] at which changed(t) holds, given !changed(lo) and changed(hi), to `resolution` seconds (or
// until the bracket's ends are adjacent doubles, when the resolution is below their spacing). A template: the test
// runs some twenty times for every change located, and a std::function call costs as much as a simple test.
template <class Changed>
double bisect(double lo, double hi, const Changed& changed, double resolution = kTimeResolution) {
  while (hi - lo > resolution) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (changed(mid) ? hi : lo) = mid;
  }
  return hi;
}

// The same for a change that is the sign of a continuous quantity: changed(t) holds where value(t) > 0 and fails where
// value(t) < 0 (a depth past a level, a height below the bed, a contact's pull). TOMS 748 (Alefeld, Potra and Shi,
// 1995) closes the bracket on the root in a handful of evaluations where bisection takes twenty to forty; bisection
// finishes what it leaves (a value with a jump, a root at an end). The answer keeps bisect's contract, changed there
// and not a resolution earlier, and is the latest such time, as bisection's falls half a resolution past the root on
// average: a step redone to end at an onset then touches by its own integration too, not on the interpolant alone
// (ending a hair short of it, it would be rejected more often).
template <class Changed, class Value>
double locate(double lo, double hi, const Changed& changed, const Value& value, double resolution = kTimeResolution) {
  const double at_lo = value(lo), at_hi = value(hi);
  if (at_lo < 0 && at_hi > 0) {
    namespace policies = boost::math::policies;
    using NoThrow = policies::policy<policies::evaluation_error<policies::ignore_error>>;
    std::uintmax_t iterations = kMaxRootIterations;
    const auto closed = [&](double a, double b) { return b - a <= resolution; };
    const auto [a, b] = boost::math::tools::toms748_solve(value, lo, hi, at_lo, at_hi, closed, iterations, NoThrow());
    const double end = hi;
    if (a > lo && value(a) < 0) lo = a;
    if (b < hi && value(b) > 0) hi = b;
    if (lo + resolution < end && changed(lo + resolution)) return lo + resolution;
  }
  return bisect(lo, hi, changed, resolution);
}

}  // namespace

const char* transition_kind(Motion from, Motion to) {
  if (from == Motion::Airborne) return "landed";
  switch (to) {
    case Motion::Stationary: return "stopped";
    case Motion::Spinning: return "spinning";
    case Motion::Rolling: return "rolling";
    case Motion::Sliding: return "sliding";
    case Motion::Airborne: return "airborne";
    case Motion::Pocketed: return "pocketed";
    case Motion::OffTable: return "off_table";
  }
  return "?";
}

const char* motion_name(Motion m) {
  static constexpr const char* names[] = {"stationary", "spinning", "rolling", "sliding", "airborne", "pocketed",
                                          "off_table"};
  return names[static_cast<int>(m)];
}

Motion classify(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                double* margin) {
  double least = 1.0;  // a margin past 1 (m or m/s) is far from any threshold: capped there
  auto decides = [&](double quantity, double threshold) { least = std::min(least, std::abs(quantity - threshold)); };
  auto answer = [&](Motion m) {
    if (margin) *margin = least;
    return m;
  };
  if (!state.in_play[i])
    return answer(model.pocket_under(position(x, i), model.balls[i].radius) ? Motion::Pocketed : Motion::OffTable);
  const double r = model.balls[i].radius;
  const Vec3 p = position(x, i), v = velocity(x, i), w = spin(x, i);
  Vec3 n{0.0};
  double best_up = -2;
  // The support is the collider within kSupportGap whose normal points most nearly up. A level floor under the ball
  // (ModelIndex::floor) is as far up as a normal goes: the other colliders need no probe (a ball on the bed, in
  // every step's scan).
  for (size_t k = 0; k < index.plane_like.size() && best_up < 1; ++k)
    if (const auto on_floor = floor_penetration(index, k, p, r); on_floor && *on_floor) {
      decides((*on_floor)->depth, -kSupportGap);
      if ((*on_floor)->depth > -kSupportGap) best_up = 1, n = kUp;
    }
  if (best_up < 1)
    near_colliders(model, index, p, r, kSupportGap, [&](int, const Penetration& pen) {
      decides(pen.depth, -kSupportGap);
      if (pen.depth > -kSupportGap && glm::dot(pen.normal, kUp) > best_up) {
        best_up = glm::dot(pen.normal, kUp);
        n = pen.normal;
      }
    });
  if (best_up == -2) return answer(Motion::Airborne);
  const double eps = model.options.rest_speed;
  const Vec3 vt = v - glm::dot(v, n) * n;
  const Vec3 u = vt + r * glm::cross(n, w);  // slip at the support (docs/model.md#slip), tangential part
  const double slip = glm::length(u - glm::dot(u, n) * n);
  decides(slip, eps);
  if (!(slip < eps)) return answer(Motion::Sliding);
  const double speed = glm::length(vt);
  decides(speed, eps);
  if (!(speed < eps)) return answer(Motion::Rolling);
  const double spinning = r * std::abs(glm::dot(w, n));  // m/s: the surface speed of the spin about the normal
  decides(spinning, eps);
  return answer(spinning < eps ? Motion::Stationary : Motion::Spinning);
}

const double* EventDetector::balls_at(const StepSpan& span, double t, const Key& key) const {
  span.interpolate_ball(t, scratch_, key.first);
  if (key.second >= 0) span.interpolate_ball(t, scratch_, key.second);
  return scratch_.data();
}

void EventDetector::collect(const State& state, const double* x, std::vector<Key>& keys) {
  const int n = state.ball_count();
  // The simulation asks first_contact_change and then scan about the same accepted state: collect it once.
  if (memo_.in_play == state.in_play && memo_.asleep == state.asleep && memo_.x.size() == size_t(9 * n) &&
      std::equal(memo_.x.begin(), memo_.x.end(), x)) {
    keys = memo_keys_;
    return;
  }
  keys.clear();
  // Sleepers' contacts cannot change while they sleep; leaving them out of the snapshot and of every later collect
  // is consistent, because the snapshot is retaken whenever a ball falls asleep or wakes.
  for (int i = 0; i < n; ++i)
    if (state.active(i)) collider_contacts(i, x, keys);
  overlapping_pairs(model_, index_, state, x, broad_);
  for (const auto& [i, j] : broad_.pairs) {
    const Key k{std::min(i, j), std::max(i, j)};
    if (depth(k, x) > kTouch) keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  memo_.in_play = state.in_play;
  memo_.asleep = state.asleep;
  memo_.x.assign(x, x + 9 * n);
  memo_keys_ = keys;
}

void EventDetector::collect(const State& state, const StepSpan& span, const StepContacts& kept,
                            const std::vector<ContactRecord>& record, std::vector<Key>& keys) {
  const double* x = span.x1.data();
  // The record holds every pair the step looked at. Another pair can touch only if its balls closed a gap wider than
  // the cap's reach: two of them moved more than that between them (pushed harder than the cap's bound on their
  // acceleration by the balls around them). Then the broad phase looks.
  if (kept.near_known) {
    double most = 0, next = 0;  // m: the two largest displacements over the span
    for (int i = 0; i < state.ball_count(); ++i) {
      if (!state.active(i)) continue;
      const double moved = glm::length(position(x, i) - position(span.x0, i));
      if (moved > most) next = most, most = moved;
      else next = std::max(next, moved);
    }
    if (most + next >= kept.reach) return collect(state, x, keys);
  }
  keys.clear();
  for (const ContactRecord& r : record)
    if (r.depth > kTouch) keys.push_back(r.key);
  // What the right-hand side left out: the colliders of a ball in the rolling or sliding regime (the bed it rests on)
  // and the contacts the step kept apart (which for a ball in a regime may already be among the former).
  for (int i = 0; i < state.ball_count(); ++i)
    if (state.active(i) && (state.rolling(i) || state.sliding(i))) collider_contacts(i, x, keys);
  for (const Key& k : kept.separated)
    if (depth(k, x) > kTouch) keys.push_back(k);
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

void EventDetector::collider_contacts(int i, const double* x, std::vector<Key>& keys) const {
  near_colliders(model_, index_, position(x, i), model_.balls[i].radius, kTouch, [&](int c, const Penetration& pen) {
    if (pen.depth > kTouch) keys.emplace_back(i, -1 - c);
  });
}

double EventDetector::depth(const Key& key, const double* x) const {
  const auto [i, other] = key;
  const double ri = model_.balls[i].radius;
  if (other >= 0) return ri + model_.balls[other].radius - glm::length(position(x, i) - position(x, other));
  const auto pen = collider_penetration(model_, index_, -1 - other, position(x, i), ri, kTouch);
  return pen ? pen->depth : -1.0;
}

ContactForce EventDetector::force_at(const Key& key, const double* x) const {
  const auto [i, other] = key;
  const Smoothing smoothing{model_.options.friction_sharpness, model_.options.friction_rate_limit};
  if (other >= 0) {
    const ContactKinematics kin = pair_kinematics(model_, index_, x, i, other);
    return kin.depth > 0 ? contact_force(index_.ball_ball(), kin, smoothing) : ContactForce{};
  }
  const double r = model_.balls[i].radius;
  const auto pen = collider_penetration(model_, index_, -1 - other, position(x, i), r, 0.0);
  if (!pen || pen->depth <= 0) return {};
  return collider_force(index_.collider_material(-1 - other), index_, i, r, velocity(x, i), spin(x, i), *pen, smoothing);
}

bool EventDetector::touches(const Key& key, const double* x) const { return depth(key, x) > 0; }

// first_law_change's two earliest changes of different contacts so far: only they are located (a contact that has not
// changed by the second is not), the first with its kind.
struct EventDetector::LawSearch {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  const StepSpan& span;
  double first_at = inf, next_at = inf;
  bool first_is_release = false;

  // Where changed(t) first holds, from `from` on, searched only as far as the changes found so far make worth it: up
  // to the first if the contact has changed by then (it becomes the first), else up to the second (it becomes the
  // second); +inf where it has changed by neither. The span's end, where every contact looked at has changed, stands
  // in for a change not found yet. find(lo, hi) locates a change bracketed there.
  template <class Changed, class Find>
  double search(const Changed& changed, double from, const Find& find) const {
    const double first = std::min(first_at, span.t1), second = std::min(next_at, span.t1);
    if (first == span.t1 || changed(first)) return find(from, first);
    if (second < span.t1 && !changed(second)) return inf;
    return find(std::max(from, first), second);
  }
  void add(double at, bool release) {
    if (at < first_at) {
      next_at = first_at;
      first_at = at;
      first_is_release = release;
    } else {
      next_at = std::min(next_at, at);
    }
  }
};

EventDetector::LawChanges EventDetector::first_law_change(const StepSpan& span, const std::vector<ContactRecord>& start,
                                                          const std::vector<ContactRecord>& end) const {
  LawSearch so_far{span};
  // Contacts within kTouch of zero depth carry nothing worth a cut (frozen balls touch at zero depth, and round-off
  // makes their forces of 1e-17 N come and go), as for contact changes.
  for (size_t a = 0, b = 0; a < start.size(); ++a) {
    const ContactRecord& s0 = start[a];
    while (b < end.size() && end[b].key < s0.key) ++b;
    if (s0.normal <= 0 || s0.depth <= kTouch) continue;
    const ContactRecord* e = b < end.size() && end[b].key == s0.key ? &end[b] : nullptr;
    if (!e || e->normal <= 0) release_change(span, s0.key, e, so_far);
    else if (e->depth > kTouch && friction_switched(s0.friction, e->friction) &&
             moves(s0.key, s0.friction, e->friction, span.t1 - span.t0))
      friction_change(span, s0, so_far);
  }
  const double inf = LawSearch::inf;
  return {so_far.first_is_release ? so_far.first_at : inf, so_far.first_is_release ? inf : so_far.first_at,
          so_far.next_at < span.t1 ? so_far.next_at : inf};
}

// A contact that pushed at the span's start and stops pushing inside it (`e`: its record at the end, if any). Located
// to 0.1 ns, past the point: the force is continuous through zero there, so a pulling force held for 0.1 ns costs an
// impulse of order (dF/dt) 1e-20 N s, and the step that follows sees the contact released. An unclamped contact that
// still touches at the end (normal < 0 there) and whose pull since the release cannot matter lets the trial stand: a
// redo aimed at the release ends a hair before or after its own, and one after it would be redone again.
void EventDetector::release_change(const StepSpan& span, const Key& k, const ContactRecord* e, LawSearch& so_far) const {
  const bool pulls = e && e->normal < 0;
  if (pulls && !pull_matters(span, k, span.t0)) return;
  auto pull_at = [&](double t) { return pull(k, balls_at(span, t, k)); };
  auto released_at = [&](double t) { return pull_at(t) >= 0; };
  const double at = so_far.search(released_at, span.t0, [&](double lo, double hi) {
    return locate(lo, hi, released_at, pull_at, kTimeResolution);
  });
  if (at < LawSearch::inf && !(pulls && !pull_matters(span, k, at))) so_far.add(at, true);
}

// A contact that pushes at both ends of the span and whose friction switched its law (friction_switched, moves): where
// the law first differs from the start's; where the contact stops pushing on the way, it has none. A switch within
// `resolution` of the start is where the last step was cut, and a band edge before `crossed` is crossed: the law after
// either is the one to keep (and a switch within `resolution` of the end is where this trial was cut).
void EventDetector::friction_change(const StepSpan& span, const ContactRecord& s0, LawSearch& so_far) const {
  const Key& k = s0.key;
  const double resolution = switch_resolution(span.t1 - span.t0);
  const double crossed = span.t0 + band_edge_share(model_.integrator.method) * (span.t1 - span.t0);
  FrictionState law = s0.friction;
  auto law_at = [&](double t) { return FrictionState(force_at(k, balls_at(span, t, k))); };
  auto switched_at = [&](double t) {
    const ContactForce f = force_at(k, balls_at(span, t, k));
    return f.normal > 0 && friction_switched(law, FrictionState(f));
  };
  // One pass for the switch at the start, one for each of the three terms' band edges crossed, one to find.
  double from = span.t0;
  for (int pass = 0; pass < 5; ++pass) {
    const double at =
        so_far.search(switched_at, from, [&](double lo, double hi) { return bisect(lo, hi, switched_at, resolution); });
    if (at >= span.t1 - resolution) break;  // +inf included
    if (at > span.t0 + resolution && (at >= crossed || pass == 4 || !band_edges_only(law, law_at(at)))) {
      so_far.add(at, false);
      return;
    }
    from = at;
    law = law_at(at);
  }
}

// A friction term whose force changes by dF (N) over a step of h seconds can move the velocities by at most about
// dF * mobility * h (the slip mobility, 3.5/m a ball, bounds what any term does to any component in m/s, the spin's
// surface speed included), so a switch whose terms change by so little that this is under 1 % of the absolute tolerance
// is no kink worth a cut: a rolling resistance crossing its band while the ball slides, where its weight is nothing,
// or a resting contact's terms stirred by round-off.
bool EventDetector::moves(const Key& k, const FrictionState& a, const FrictionState& b, double h) const {
  const double df = glm::length(b.friction - a.friction) + glm::length(b.rolling - a.rolling) +
                    std::abs(b.spin_torque - a.spin_torque) / model_.balls[k.first].radius;
  return df * mobility(k) * h >= kSwitchMoveShare * model_.integrator.abs_tol;
}

// Whether the pull of a contact released at `from` can matter by the span's end: the most it pulls on the way,
// sampled at the end and at a quarter, half and three quarters of the way (a pull need not grow all the way: under
// Hunt-Crossley damping it falls back to zero with the depth), times its slip mobility and the time, against the share
// of abs_tol that moves() allows a friction switch. The slip mobility also bounds the friction the negative force
// drives backwards (add_friction runs unclamped; mu <= 1). A contact that stopped touching pulls 1 N: it matters.
bool EventDetector::pull_matters(const StepSpan& span, const Key& k, double from) const {
  const double h = span.t1 - from;
  double most = 0;
  for (const double share : {1.0, 0.75, 0.5, 0.25}) most = std::max(most, pull(k, balls_at(span, from + share * h, k)));
  return most * mobility(k) * h >= kSwitchMoveShare * model_.integrator.abs_tol;
}

double EventDetector::mobility(const Key& k) const {
  double m = index_.inv_mass[k.first] + index_.inv_inertia_r2[k.first];
  if (k.second >= 0) m += index_.inv_mass[k.second] + index_.inv_inertia_r2[k.second];
  return m;
}

double EventDetector::pull(const Key& key, const double* x) const {
  const auto [i, other] = key;
  const double ri = model_.balls[i].radius;
  if (other >= 0) {
    const Vec3 d = position(x, i) - position(x, other);
    const double dist = glm::length(d), depth = ri + model_.balls[other].radius - dist;
    if (depth <= 0) return 1.0;
    return -normal_force(index_.ball_ball(), depth, -glm::dot(velocity(x, i) - velocity(x, other), d) / dist);
  }
  const auto pen = collider_penetration(model_, index_, -1 - other, position(x, i), ri, 0.0);
  if (!pen || pen->depth <= 0) return 1.0;
  return -normal_force(index_.collider_material(-1 - other), pen->depth, -glm::dot(velocity(x, i), pen->normal));
}

double EventDetector::crossing(const StepSpan& span, const Key& key, bool begins, double resolution,
                               double level) const {
  auto deeper = [&](double s) { return depth(key, balls_at(span, s, key)) - level; };
  return locate(span.t0, span.t1, [&](double s) { return (deeper(s) > 0) == begins; },
                [&](double s) { return begins ? deeper(s) : -deeper(s); }, resolution);
}

double EventDetector::first_touch(const StepSpan& span, const std::vector<ContactKey>& separated, ContactKey* which) {
  double at = std::numeric_limits<double>::infinity();
  for (const Key& k : separated) {
    if (!touches(k, span.x1.data())) continue;
    const double t = crossing(span, k, true, kOnsetResolution, 0.0);
    if (t < at && which) *which = k;
    at = std::min(at, t);
  }
  return at;
}

double EventDetector::time_to_touch(const StepSpan& span, const ContactKey& key) const {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double* x = span.x1.data();
  const auto [i, other] = key;
  double gap, closing;
  if (other >= 0) {
    const Vec3 d = position(x, i) - position(x, other);
    const double dist = glm::length(d);
    gap = dist - model_.balls[i].radius - model_.balls[other].radius;
    if (gap < 0) return 0.0;
    closing = -glm::dot(velocity(x, i) - velocity(x, other), d) / dist;
  } else {
    const auto pen = collider_penetration(model_, index_, -1 - other, position(x, i), model_.balls[i].radius);
    if (!pen) return inf;
    gap = -pen->depth;
    if (gap < 0) return 0.0;
    closing = -glm::dot(velocity(x, i), pen->normal);
  }
  return gap < kTouch && closing > 0 ? gap / closing : inf;
}

std::string EventDetector::body_name(int other) const {
  return other >= 0 ? model_.balls[other].id : model_.colliders[-1 - other].name;
}

void EventDetector::reset(const State& state) {
  // A contact that scan let begin at zero depth (a step ended at its onset) is not yet kTouch deep: a restart there
  // (a regime change at the same step's end) keeps it rather than reporting it again once it gets that deep.
  std::vector<Key> onsets;
  for (const Key& k : contacts_)
    if (state.active(k.first) && (k.second < 0 || state.active(k.second)) && depth(k, state.x.data()) > 0)
      onsets.push_back(k);
  collect(state, state.x.data(), contacts_);
  for (const Key& k : onsets)
    if (const auto at = std::lower_bound(contacts_.begin(), contacts_.end(), k); at == contacts_.end() || *at != k)
      contacts_.insert(at, k);
  motion_.resize(state.ball_count());
  for (int i = 0; i < state.ball_count(); ++i) motion_[i] = classify(model_, index_, state, state.x.data(), i);
}

void EventDetector::changes(const State& state, const StepSpan& span, const StepContacts& kept,
                            const std::vector<ContactRecord>* record) {
  std::vector<Key> &now = now_, &begun = begun_, &ended = ended_;
  if (record) collect(state, span, kept, *record, now);
  else collect(state, span.x1.data(), now);
  begun.clear();
  ended.clear();
  std::set_difference(now.begin(), now.end(), contacts_.begin(), contacts_.end(), std::back_inserter(begun));
  std::set_difference(contacts_.begin(), contacts_.end(), now.begin(), now.end(), std::back_inserter(ended));
}

// A contact that pushed nothing at the step's start (released: separating with its force clamped at zero) ends with
// zero force on both sides: its end is no kink.
bool EventDetector::released_at_start(const Key& k, const std::vector<ContactRecord>* start) {
  if (!start) return false;
  const auto r = std::lower_bound(start->begin(), start->end(), k,
                                  [](const ContactRecord& c, const Key& key) { return c.key < key; });
  return r != start->end() && r->key == k && r->normal <= 0;
}

EventDetector::Changes EventDetector::first_contact_change(const StepSpan& span, const State& state,
                                                           const StepContacts& kept,
                                                           const std::vector<ContactRecord>* record,
                                                           const std::vector<ContactRecord>* start) {
  changes(state, span, kept, record);
  constexpr double inf = std::numeric_limits<double>::infinity();
  Changes first{inf, inf};
  // Frozen balls touch at zero depth, and round-off flips them in and out of contact: no kink worth a restart.
  auto earliest = [&](const Key& k, const StateVector& apart, bool begins, double& at) {
    if (depth(k, apart.data()) > -kTouch) return;
    at = std::min(at, crossing(span, k, begins, kTimeResolution));
  };
  for (const Key& k : begun_) earliest(k, span.x0, true, first.begin);
  for (const Key& k : ended_)
    if (!released_at_start(k, start)) earliest(k, span.x1, false, first.end);
  return first;
}

void EventDetector::scan(const StepSpan& span, const State& state, const StepContacts& kept,
                         const std::vector<ContactRecord>* record, std::vector<Event>& events, std::vector<Exit>& exits) {
  auto ball_at = [&](double t, int i) { return balls_at(span, t, Key{i, -1}); };
  const size_t first_new = events.size();

  // Balls leaving play: the centre falls a radius below the bed (y = 0), through a pocket or off the table.
  for (int i = 0; i < state.ball_count() && model_.balls_leave_below_bed; ++i) {
    if (!state.active(i)) continue;
    const double r = model_.balls[i].radius;
    if (span.x1[9 * i + 1] >= -r) continue;
    const double t = locate(span.t0, span.t1, [&](double s) { return ball_at(s, i)[9 * i + 1] < -r; },
                            [&](double s) { return -r - ball_at(s, i)[9 * i + 1]; });
    const Vec3 p = position(ball_at(t, i), i);
    const Pocket* pocket = model_.pocket_under(p, r);
    events.push_back({t, pocket ? "pocketed" : "off_table",
                      pocket ? std::vector<std::string>{model_.balls[i].id, pocket->name}
                             : std::vector<std::string>{model_.balls[i].id}});
    exits.push_back({i, t});
  }

  // Contacts that began or ended: set difference of sorted key lists, each change located on its own depth.
  changes(state, span, kept, record);
  std::vector<Key>& now = now_;
  for (const Key& k : begun_)
    events.push_back({crossing(span, k, true, kTimeResolution), "contact_begin",
                      {model_.balls[k.first].id, body_name(k.second)}});
  for (const Key& k : ended_)
    events.push_back({crossing(span, k, false, kTimeResolution), "contact_end",
                      {model_.balls[k.first].id, body_name(k.second)}});
  // A step that ends where a contact left out of it touches (first_touch) ends at the contact's onset, at zero
  // depth: the next step may carry the whole contact (a glancing one lasts 50 us), so it begins here.
  for (const Key& k : kept.separated) {
    const auto at_k = std::lower_bound(now.begin(), now.end(), k);
    if ((at_k != now.end() && *at_k == k) || depth(k, span.x1.data()) <= 0) continue;
    now.insert(at_k, k);
    events.push_back({span.t1, "contact_begin", {model_.balls[k.first].id, body_name(k.second)}});
  }
  contacts_.swap(now);

  // Motion state changes (a sleeper stays stationary).
  for (int i = 0; i < state.ball_count(); ++i) {
    if (!state.active(i)) continue;
    const Motion m1 = classify(model_, index_, state, span.x1.data(), i);
    if (m1 == motion_[i]) continue;
    const Motion m0 = motion_[i];
    // Located on the margin (classify), which crosses zero where the motion changes.
    auto moved_on = [&](double s) { return classify(model_, index_, state, ball_at(s, i), i) != m0; };
    auto past = [&](double s) {
      double margin;
      return classify(model_, index_, state, ball_at(s, i), i, &margin) != m0 ? margin : -margin;
    };
    const double t = locate(span.t0, span.t1, moved_on, past);
    events.push_back({t, transition_kind(m0, m1), {model_.balls[i].id}});
    motion_[i] = m1;
  }
  // A ball that left play inside the step is frozen from then on (Island::settle): what the step's interpolant has it
  // do later (land on the pocket's floor, touch the pocket's back) never happened.
  for (const Exit& x : exits)
    events.erase(std::remove_if(events.begin() + first_new, events.end(), [&](const Event& e) {
                   return e.time > x.time && std::find(e.bodies.begin(), e.bodies.end(), model_.balls[x.ball].id) !=
                                                 e.bodies.end();
                 }), events.end());
  std::stable_sort(events.begin() + first_new, events.end(),
                   [](const Event& a, const Event& b) { return a.time < b.time; });
}

}  // namespace shotlab
