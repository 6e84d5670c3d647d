#include "contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>


namespace shotlab {

namespace {

// Time for a gap (m) to close at initial closing speed s (m/s; negative: opening) and closing acceleration at most a
// (m/s^2): the positive root of gap = s t + a t^2 / 2, written to stay accurate when a or s is small.
double closing_time(double gap, double s, double a) {
  const double root = std::sqrt(s * s + 2.0 * a * gap);
  if (s < 0) return a > 0 ? (root - s) / a : std::numeric_limits<double>::infinity();  // turns back first
  const double den = s + root;
  return den > 0 ? 2.0 * gap / den : std::numeric_limits<double>::infinity();
}

}  // namespace

void refresh_sleepers(const Model& model, const State& state, const double* x, BroadPhase& broad) {
  // The key is the flags the list was built for, compared in place: this runs in every broad phase.
  const size_t n = state.in_play.size();
  auto& key = broad.sleep_key;
  if (n > 0 && key.size() == n + state.asleep.size() && std::equal(state.in_play.begin(), state.in_play.end(), key.begin()) &&
      std::equal(state.asleep.begin(), state.asleep.end(), key.begin() + n))
    return;
  key = state.in_play;
  key.insert(key.end(), state.asleep.begin(), state.asleep.end());
  broad.sleepers.clear();
  for (int i = 0; i < state.ball_count(); ++i)
    if (state.in_play[i] && state.sleeping(i)) broad.sleepers.push_back(i);
  auto left = [&](int i) { return x[9 * i] - model.balls[i].radius; };
  std::sort(broad.sleepers.begin(), broad.sleepers.end(), [&](int a, int b) { return left(a) < left(b); });
  broad.sleeper_left.clear();
  for (int i : broad.sleepers) broad.sleeper_left.push_back(left(i));
}

void overlapping_pairs(const Model& model, const ModelIndex& index, const State& state, const double* x,
                       BroadPhase& broad, double slack, bool sleeping_pairs) {
  broad.pairs.clear();
  sweep_pairs(model, index, state, x, broad, slack, sleeping_pairs, [&](int i, int j) {
    const Vec3 d = position(x, i) - position(x, j);
    const double reach = model.balls[i].radius + model.balls[j].radius + slack;
    if (glm::dot(d, d) < reach * reach) broad.pairs.emplace_back(i, j);
  });
}

namespace {

// s: the longest a point at horizontal offset d (m) from an axis, moving at v, stays within `radius` of it on a
// straight path; +inf if it does not move across.
double time_in_circle(const Vec3& d, const Vec3& v, double radius) {
  const double A = v.x * v.x + v.z * v.z, B = 2 * (d.x * v.x + d.z * v.z), C = d.x * d.x + d.z * d.z - radius * radius;
  if (A == 0) return std::numeric_limits<double>::infinity();
  const double q = std::sqrt(std::max(0.0, B * B - 4 * A * C));
  return B > 0 ? -2 * C / (B + q) : (q - B) / (2 * A);
}

// s: a lower bound on when a ball whose centre is rho < inner (m) from an arc wall's axis (horizontal offset d,
// velocity v) leaves the cylinder of radius `inner`, its horizontal acceleration at most `across` (m/s^2), within
// `horizon`.
// Up to any h the path strays from the straight one by at most across h^2 / 2, so the centre stays within the
// cylinder shrunk by that much until min(h, the straight path's time in it); the best h is where the two meet, found
// by bisection on log h from `floor`, a bound already known.
double time_inside_arc(const Vec3& d, const Vec3& v, double rho, double inner, double across, double horizon,
                       double floor) {
  auto leave = [&](double h) {
    const double radius = inner - 0.5 * across * h * h;
    return rho < radius ? time_in_circle(d, v, radius) : 0.0;
  };
  double best = std::max(floor, leave(horizon));
  if (best >= horizon || !(best > 0)) return best;
  double lo = best, hi = horizon;
  for (int k = 0; k < 8; ++k) {
    const double h = std::sqrt(lo * hi), t = leave(h);
    best = std::max(best, std::min(h, t));
    (t >= h ? lo : hi) = h;
  }
  return best;
}

// s: a lower bound on when a ball (as for collider_closing_time) closes `gap` (m) to an arc wall, `margin` of it past
// touching. D, the distance to the wall, falls at most at |v|. Every point of the wall lies between the cylinders of
// radius `radius` and `radius + thickness` about its axis: from inside the inner one the ball's centre first has to
// leave the cylinder of radius `radius - r + margin` (time_inside_arc), from outside the outer one reach that
// cylinder, widened by r, whose distance is convex.
double arc_wall_closing_time(const ArcWall& wall, const Vec3& p, double r, const Vec3& v, double gap, double margin,
                             const AccelBound& a, double horizon) {
  const double anyway = closing_time(gap, glm::length(v), a.total);
  const Vec3 d{p.x - wall.center.x, 0.0, p.z - wall.center.z};
  const double rho = glm::length(d), outside = rho - wall.radius - wall.thickness - r;
  if (outside > 0) return std::max(anyway, closing_time(margin + outside, -glm::dot(v, d) / rho, a.total));
  return time_inside_arc(d, v, rho, wall.radius - r + margin, a.across, horizon, anyway);
}

// s: a lower bound on when a ball (centre p, radius r, velocity v, acceleration at most a) closes `gap` (m) to a
// collider it misses by -pen.depth, within `horizon` (docs/model.md#step-cap). Its distance D to the collider changes
// at D' = v.n now (n = pen.normal, D's gradient), and D'' >= -a: D is linear for a plane (also over its holes' edges
// when it is outside them) and convex for a sphere's centre or a capsule's axis. Over a hole of radius rho, D is the
// distance to the rim circle, concave along the rim by at most 1 / (rho - D): D'' >= -(V^2 / (rho - D) + a), V the
// speed bound, while the centre keeps rho - D above half its value now; the later of that bound and the 1-Lipschitz
// one (D falls at most at |v|) holds. With |v| everywhere a ball moving along a cushion, or falling past a pocket's
// rim, would approach it in ever smaller steps. An arc wall is not convex (its nearest point may lie behind a ball
// that crosses towards its far side): arc_wall_closing_time.
double collider_closing_time(const Shape& shape, const Vec3& p, double r, const Vec3& v, const Penetration& pen,
                             double gap, const AccelBound& bound, double horizon) {
  if (const auto* wall = std::get_if<ArcWall>(&shape))
    return arc_wall_closing_time(*wall, p, r, v, gap, gap + pen.depth, bound, horizon);
  const double a = bound.total;
  const double rate = glm::dot(v, pen.normal);
  const Hole* hole = hole_over(shape, p);
  if (!hole) return closing_time(gap, -rate, a);
  const double room = hole->radius - (r - pen.depth), speed0 = glm::length(v);  // room: rho - D now
  const double anyway = closing_time(gap, speed0, a);  // D falls at most at |v| (it is 1-Lipschitz)
  if (room <= 0) return anyway;
  // Until h the centre moves less than room / 2, so rho - D stays above room / 2; the bound holds that long. Near the
  // hole's axis (room small, the rim far) the first bound is the better one.
  const double h = std::min(horizon, 0.5 * room / (speed0 + a * horizon)), speed = speed0 + a * h;
  return std::max(anyway, std::min(h, closing_time(gap, -rate, speed * speed / (0.5 * room) + a)));
}

}  // namespace

// Time for two balls (centre offset d0 = p_i - p_j, relative velocity v) to come within `reach` of each other on
// straight paths: the smaller root of |d0 + v t| = reach; +inf when they pass wider than that. Exact for straight
// motion (a glancing pass does not approach in ever smaller steps); accelerations, which bend the paths, are covered
// by cutting the step where a contact actually begins (simulation.cpp).
double straight_line_contact_time(const Vec3& d0, const Vec3& v, double reach) {
  const double A = glm::dot(v, v), B = 2.0 * glm::dot(d0, v), C = glm::dot(d0, d0) - reach * reach;
  if (C <= 0) return 0.0;
  const double disc = B * B - 4 * A * C;
  if (B >= 0 || A == 0 || disc < 0) return std::numeric_limits<double>::infinity();
  return 2 * C / (-B + std::sqrt(disc));
}

// Straight relative motion, its target widened by how far the accelerations can bend the paths within h (a sliding
// ball curves at mu g). A pair already near that widened reach is bounded by its relative speed instead, which never
// asks for less than gap / speed: a step cannot stall at the widened boundary.
double pair_contact_time(const Vec3& d0, const Vec3& v, double reach, double a, double h) {
  const double bend = 0.5 * a * h * h, dist = glm::length(d0);
  if (dist <= reach) return 0.0;  // within reach now (closing_time wants a positive gap)
  return dist < reach + 2 * bend ? closing_time(dist - reach, glm::length(v), a)
                                 : straight_line_contact_time(d0, v, reach + bend);
}

namespace {

// Whether a contact at `depth` (m) closing at `speed` (m/s) begins at the step's start: it is within kTouch of zero
// depth, or just past it by as far as the contact got in the time a located onset may lie past its root
// (EventDetector::first_contact_change locates onsets where the depth passes kTouch, to kTimeResolution).
bool begins(double depth, double speed) { return speed > 0 && std::abs(depth) < kTouch + speed * kTimeResolution; }

// A contact of material m begins at the step's start, closing at `speed` (m/s); inv_mass: 1/kg of the lighter body.
// The step keeps the strongest onset (StepContacts::onset_strength). The strength leaves out damping: linear damping
// adds a force c v that is there from the start (no singular part), and Hunt-Crossley's factor 1 + c d' is within a
// per cent of 1 over the first steps of a contact at billiard speeds.
void note_onset(StepContacts& step, const ContactMaterial& m, double speed, double inv_mass) {
  step.onset = true;
  const double strength = m.stiffness * std::pow(speed, m.exponent) * inv_mass;
  if (strength <= step.onset_strength) return;
  step.onset_strength = strength;
  step.onset_exponent = m.exponent;
  step.onset_speed = speed;
}

// A contact deeper than kTouch (m) closing at `rate` (m/s) that pushes, but with less than half its elastic force: it is
// separating and may stop pushing within a step. Contacts further from the clamp stay off StepContacts::pushing, which
// costs a check of every listed contact on every step (a resting ball's bed contact, a rack's every pair).
bool may_release(const ContactMaterial& m, double depth, double rate) {
  if (depth <= kTouch || rate >= 0) return false;  // damping pulls only while the bodies separate
  const double fn = normal_force(m, depth, rate);
  return fn > 0 && fn < 0.5 * normal_force(m, depth, 0.0);
}

// s: when a flying ball within kSupportGap of a plane (a support, EventDetector's classify) and moving off it gets a
// millionth past kSupportGap away, on its parabola; +inf when it does not. A flight step that ends there does not span
// the ball's leaving its support and coming back, which would hide its airborne and landed events from the detector
// (it compares a step's ends).
double support_exit_time(const Model& model, const ModelIndex& index, const double* x, int i) {
  const Vec3 p = position(x, i), v = velocity(x, i);
  double best = std::numeric_limits<double>::infinity();
  near_colliders(model, index, p, model.balls[i].radius, kSupportGap, [&](int c, const Penetration& pen) {
    const Vec3& n = index.plane_normal[c];
    if (pen.depth <= -kSupportGap || glm::dot(pen.normal, n) < 1.0 - 1e-12) return;  // planes, not a hole's rim
    const double rate = glm::dot(v, n), acc = glm::dot(model.options.gravity, n);
    if (!(rate > 0 || acc > 0)) return;
    // -pen.depth + rate t + acc t^2 / 2 = target: the smaller positive root, written without cancellation.
    const double c0 = -pen.depth - kSupportGap * (1.0 + 1e-6), disc = rate * rate - 2.0 * acc * c0;
    if (disc >= 0) best = std::min(best, 2.0 * c0 / (-rate - std::sqrt(disc)));
  });
  return best;
}

}  // namespace

bool clear_of_contacts(const Model& model, const ModelIndex& index, const State& state, const double* x, int i) {
  const double margin = model.options.contact_margin, r = model.balls[i].radius;
  const Vec3 p = position(x, i);
  for (int j = 0; j < state.ball_count(); ++j)
    if (j != i && state.in_play[j] && glm::length(p - position(x, j)) - r - model.balls[j].radius < margin) return false;
  bool near = false;
  near_colliders(model, index, p, r, margin, [&](int, const Penetration& pen) { near = near || pen.depth > -margin; });
  return !near;
}

double free_acceleration(const State& state, const ModelIndex& index, int i) {
  const double g = index.gravity;
  if (state.rolling(i)) return index.collider_material(state.rolling_on[i]).rolling_resistance * g;
  if (state.sliding(i)) {
    const ContactMaterial& m = index.collider_material(state.sliding_on[i]);
    return (m.friction + m.rolling_resistance) * g;
  }
  return 2.0 * g;
}

double collider_contact_time(const Model& model, const ModelIndex& index, const State& state, const double* x, int i,
                             double horizon, AccelBound bound, StepContacts* step, int bounce_bed) {
  const double a = bound.total;
  const double margin = model.options.contact_margin;
  const Vec3 p = position(x, i), v = velocity(x, i);
  const double s = glm::length(v);
  double best = std::numeric_limits<double>::infinity();
  // Colliders farther than the ball can travel within the horizon cannot limit the step.
  const double travel = s * horizon + a * horizon * horizon + margin;
  near_colliders(model, index, p, model.balls[i].radius, travel, [&](int c, const Penetration& pen) {
    if (step) step->colliders.push_back(c);
    if (c == bounce_bed) {  // followed by the bounce; left out while apart (also just lifted off), its onset recorded
      if (step && (pen.depth <= -kTouch || (pen.depth <= 0 && glm::dot(v, pen.normal) > 0)))
        step->separated.emplace_back(i, -1 - c);
      return;
    }
    if (pen.depth <= 0) {
      const double t = collider_closing_time(model.colliders[c].shape, p, model.balls[i].radius, v, pen, margin - pen.depth,
                                             bound, horizon);
      best = std::min(best, t);
      if (step && pen.depth <= -kTouch && t <= horizon) step->separated.emplace_back(i, -1 - c);
    }
    if (!step) return;
    if (begins(pen.depth, -glm::dot(v, pen.normal)))
      note_onset(*step, index.collider_material(c), -glm::dot(v, pen.normal), index.inv_mass[i]);
    if (may_release(index.collider_material(c), pen.depth, -glm::dot(v, pen.normal))) step->pushing.emplace_back(i, -1 - c);
  });
  // A ball in the rolling or sliding regime, or bouncing, ignores its support's geometry: it must not move far over a
  // pocket's edge.
  const int bed = state.rolling(i) ? state.rolling_on[i] : state.sliding(i) ? state.sliding_on[i] : bounce_bed;
  if (bed >= 0) best = std::min(best, closing_time(hole_gap(model.colliders[bed].shape, p) + margin, s, a));
  return best;
}

double time_to_possible_contact(const Model& model, const ModelIndex& index, const State& state, const double* x,
                                double horizon, BroadPhase& broad, StepContacts* step, bool flight,
                                const std::vector<BedBounce>* bounces) {
  if (step) {  // every field reset, the lists keeping their storage
    *step = StepContacts{.separated = std::move(step->separated), .pushing = std::move(step->pushing),
                         .near = std::move(step->near), .colliders = std::move(step->colliders),
                         .collider_from = std::move(step->collider_from)};
    step->separated.clear(), step->pushing.clear(), step->near.clear(), step->colliders.clear();
    step->collider_from.assign(state.ball_count() + 1, 0);
  }
  // Relative acceleration bound outside contacts: gravity plus cloth friction, generously twice |g|. A pair pushed
  // harder by third balls may start touching inside a step; the simulation then cuts the step at the onset.
  const double a_free = 2.0 * index.gravity;
  // In flight (the caller moves every ball in closed form) a ball in the full model that no rod holds touches nothing
  // until the step's first onset, where the step ends: gravity alone accelerates it, across only by its horizontal
  // part (none unless gravity is tilted).
  auto bounce = [&](int i) -> const BedBounce* {
    if (bounces)
      for (const BedBounce& b : *bounces)
        if (b.ball == i) return &b;
    return nullptr;
  };
  auto flies = [&](int i) {
    return flight && state.active(i) && !state.rolling(i) && !state.sliding(i) && index.rods_on[i] == 0 && !bounce(i);
  };
  auto accel = [&](int i) {
    const BedBounce* b = bounce(i);
    return b ? b->accel : flies(i) ? index.gravity : free_acceleration(state, index, i);
  };
  const double margin = model.options.contact_margin;
  double best = std::numeric_limits<double>::infinity();
  double vmax = 0, abounce = 0;  // m/s, m/s^2: the fastest ball, the largest bound of a bouncing one
  const int n = state.ball_count();
  for (int i = 0; i < n; ++i) {
    if (step) step->collider_from[i] = static_cast<int>(step->colliders.size());
    if (!state.active(i)) continue;  // a sleeping ball does not move towards anything
    vmax = std::max(vmax, glm::length(velocity(x, i)));
    if (const BedBounce* b = bounce(i)) abounce = std::max(abounce, b->accel);
    const double a = accel(i);
    const BedBounce* b = bounce(i);
    const AccelBound bound{a, b ? b->across : flies(i) ? index.gravity_across : a};
    best = std::min(best, collider_contact_time(model, index, state, x, i, horizon, bound, step, b ? b->bed : -1));
    if (flies(i)) best = std::min(best, support_exit_time(model, index, x, i));
  }
  if (step) step->collider_from[n] = static_cast<int>(step->colliders.size()), step->colliders_known = true;
  // Ball pairs whose x gap is within anything closable within the horizon (a sleeper does not move: only the awake
  // one closes in).
  const double h = std::min(best, horizon);
  auto sort = [&] {
    if (step) std::sort(step->separated.begin(), step->separated.end()), std::sort(step->pushing.begin(), step->pushing.end());
  };
  if (h <= 0) {
    sort();
    return best;
  }
  // Straight relative motion, its target widened by how far accelerations can bend the paths within the horizon
  // (pair_contact_time).
  const double reach = 2.0 * vmax * h + std::max(a_free, 2.0 * abounce) * h * h;
  sweep_pairs(model, index, state, x, broad, reach, false, [&](int i, int j) {
    const double ai = accel(i), aj = accel(j);
    const double a = (ai == a_free || aj == a_free) && !bounce(i) && !bounce(j) ? a_free : ai + aj;
    const Vec3 d0 = position(x, i) - position(x, j), v = velocity(x, i) - velocity(x, j);
    const double ri = model.balls[i].radius, rj = model.balls[j].radius, dist = glm::length(d0);
    const double closing = -glm::dot(v, d0) / dist;  // m/s
    if (step && begins(ri + rj - dist, closing))
      note_onset(*step, index.ball_ball(), closing, std::max(index.inv_mass[i], index.inv_mass[j]));
    if (dist <= ri + rj) {  // already touching: the contact force is resolved by error control
      if (!step) return;
      step->near.emplace_back(i, j);
      if (may_release(index.ball_ball(), ri + rj - dist, closing))
        step->pushing.emplace_back(std::min(i, j), std::max(i, j));
      return;
    }
    // Relative motion: balls moving together, as a broken rack does, do not hold each other's steps back.
    const double t = pair_contact_time(d0, v, ri + rj - margin, a, h);
    best = std::min(best, t);
    if (!step) return;
    if (dist - ri - rj >= kTouch && t <= horizon) step->separated.emplace_back(std::min(i, j), std::max(i, j));
    else step->near.emplace_back(i, j);
  });
  if (step) step->near_known = true, step->reach = reach;
  sort();
  return best;
}

}  // namespace shotlab
