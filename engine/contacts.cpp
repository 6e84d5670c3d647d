#include "contacts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>


namespace shotlab {

namespace {

// The height (m) of a plane-like shape if it is a level floor over the column: normal exactly up, a bounded plane
// spanned by level edges and covering the column (its four corners do: the region is convex); NaN for any other
// shape. The column is cleared of each hole's square. Over what is left, Probe::surface reduces to depth =
// r - (p.y - y) and normal up, exactly: the dot product with (0, 1, 0) adds two zeros.
double level_floor(const Shape& shape, ColumnXZ& column) {
  constexpr double no = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Hole>* holes = nullptr;
  double y = no;
  if (const auto* s = std::get_if<Plane>(&shape)) {
    if (s->normal != kUp) return no;
    holes = &s->holes, y = s->point.y;
  } else if (const auto* s = std::get_if<BoundedPlane>(&shape)) {
    if (s->normal != kUp || s->u.y != 0 || s->v.y != 0) return no;
    for (const double x : {column.lo_x, column.hi_x})
      for (const double z : {column.lo_z, column.hi_z}) {
        const Vec3 d = Vec3{x, s->origin.y, z} - s->origin;
        const double du = glm::dot(d, s->u), dv = glm::dot(d, s->v);
        if (du <= 0 || du >= s->uu || dv <= 0 || dv >= s->vv) return no;
      }
    holes = &s->holes, y = s->origin.y;
  } else {
    return no;
  }
  for (const Hole& h : *holes) column.exclude(h.center - h.radius, h.center + h.radius);
  return y;
}

}  // namespace

void ColumnXZ::exclude(const Vec3& lo, const Vec3& hi) {
  if (hi.x <= lo_x || lo.x >= hi_x || hi.z <= lo_z || lo.z >= hi_z) return;
  const double w = hi_x - lo_x, d = hi_z - lo_z;
  const double keep[4] = {(hi_x - hi.x) * d, (lo.x - lo_x) * d, (hi_z - hi.z) * w, (lo.z - lo_z) * w};
  switch (std::max_element(keep, keep + 4) - keep) {
    case 0: lo_x = hi.x; break;
    case 1: hi_x = lo.x; break;
    case 2: lo_z = hi.z; break;
    default: hi_z = lo.z;
  }
}

ContactCache::ContactCache(const Model& model)
    : ball_ball(&model.material(kBallBall)), gravity(glm::length(model.options.gravity)) {
  // Every island builds several of these (a new island every few collisions): one allocation per table, not one per
  // doubling of it.
  const size_t colliders = model.colliders.size(), balls = model.balls.size();
  collider_material.reserve(colliders);
  collider_bounds.reserve(colliders);
  plane_normal.reserve(colliders);
  others.reserve(colliders);
  inv_mass.reserve(balls);
  inv_inertia_r2.reserve(balls);
  for (const Collider& c : model.colliders) {
    collider_material.push_back(&model.material(c.material));
    collider_bounds.push_back(bounds(c.shape));
    if (const auto* s = std::get_if<Plane>(&c.shape)) plane_normal.push_back(s->normal);
    else if (const auto* s = std::get_if<BoundedPlane>(&c.shape)) plane_normal.push_back(s->normal);
    else plane_normal.emplace_back(0.0);
  }
  // The clear column: the span of the other colliders' bounds, cleared of each of them in the order of the model.
  bool any = false;
  for (size_t c = 0; c < model.colliders.size(); ++c) {
    if (plane_normal[c] != Vec3{0.0}) {
      plane_like.push_back(static_cast<int>(c));
      continue;
    }
    others.push_back(static_cast<int>(c));
    const Bounds& b = collider_bounds[c];
    if (!any) clear = {b.lo.x, b.hi.x, b.lo.z, b.hi.z}, any = true;
    clear.lo_x = std::min(clear.lo_x, b.lo.x), clear.hi_x = std::max(clear.hi_x, b.hi.x);
    clear.lo_z = std::min(clear.lo_z, b.lo.z), clear.hi_z = std::max(clear.hi_z, b.hi.z);
  }
  for (size_t c = 0; c < model.colliders.size() && any; ++c)
    if (plane_normal[c] == Vec3{0.0}) clear.exclude(collider_bounds[c].lo, collider_bounds[c].hi);
  floor_of.assign(model.colliders.size(), -1);
  for (size_t k = 0; k < plane_like.size(); ++k) floor_of[plane_like[k]] = static_cast<int>(k);
  // A bounded plane's floor is worked out over its own extent (inset by a nanometre: level_floor wants the corners
  // strictly inside), so that a ball near a cushion, outside the clear column, finds the bed the fast way too.
  for (int c : plane_like) {
    const Bounds& b = collider_bounds[c];
    const bool bounded = std::holds_alternative<BoundedPlane>(model.colliders[c].shape);
    floor.push_back(bounded ? ColumnXZ{b.lo.x + kFloorInset, b.hi.x - kFloorInset, b.lo.z + kFloorInset, b.hi.z - kFloorInset} : clear);
    floor_y.push_back(level_floor(model.colliders[c].shape, floor.back()));
    if (std::isnan(floor_y.back())) floor.back() = ColumnXZ{};
  }
  for (const BallSpec& b : model.balls) {
    inv_mass.push_back(1.0 / b.mass);
    inv_inertia_r2.push_back(b.radius * b.radius / b.inertia());
  }
}

namespace {

// Time for a gap (m) to close at initial closing speed s (m/s) and closing acceleration at most a (m/s^2):
// the positive root of gap = s t + a t^2 / 2, written to stay accurate when a or s is small.
double closing_time(double gap, double s, double a) {
  const double den = s + std::sqrt(s * s + 2.0 * a * gap);
  return den > 0 ? 2.0 * gap / den : std::numeric_limits<double>::infinity();
}

}  // namespace

void refresh_sleepers(const Model& model, const State& state, const double* x, ContactCache& cache) {
  // The key is the flags the list was built for, compared in place: this runs in every broad phase.
  const size_t n = state.in_play.size();
  auto& key = cache.sleep_key;
  if (n > 0 && key.size() == n + state.asleep.size() && std::equal(state.in_play.begin(), state.in_play.end(), key.begin()) &&
      std::equal(state.asleep.begin(), state.asleep.end(), key.begin() + n))
    return;
  key = state.in_play;
  key.insert(key.end(), state.asleep.begin(), state.asleep.end());
  cache.sleepers.clear();
  cache.max_radius = 0;
  for (int i = 0; i < state.ball_count(); ++i) {
    cache.max_radius = std::max(cache.max_radius, model.balls[i].radius);
    if (state.in_play[i] && state.sleeping(i)) cache.sleepers.push_back(i);
  }
  auto left = [&](int i) { return x[9 * i] - model.balls[i].radius; };
  std::sort(cache.sleepers.begin(), cache.sleepers.end(), [&](int a, int b) { return left(a) < left(b); });
  cache.sleeper_left.clear();
  for (int i : cache.sleepers) cache.sleeper_left.push_back(left(i));
}

void overlapping_pairs(const Model& model, const State& state, const double* x, ContactCache& cache, double slack,
                       bool sleeping_pairs) {
  cache.pairs.clear();
  sweep_pairs(model, state, x, cache, slack, sleeping_pairs, [&](int i, int j) {
    const Vec3 d = position(x, i) - position(x, j);
    const double reach = model.balls[i].radius + model.balls[j].radius + slack;
    if (glm::dot(d, d) < reach * reach) cache.pairs.emplace_back(i, j);
  });
}

namespace {

// Bound on how fast a ball at p moving at v can close its gap to a collider. Using |v| everywhere would make a ball
// moving along a cushion approach it in ever smaller steps (each step closing only the normal share of the gap);
// planes close at the normal speed exactly, a capsule's side at the speed across its axis.
double collider_closing_speed(const Shape& shape, const Vec3& p, const Vec3& v) {
  if (hole_gap(shape, p) == 0) return glm::length(v);  // over a pocket the gap is to the rim, closing any way
  if (const auto* s = std::get_if<Plane>(&shape)) return std::max(0.0, -glm::dot(v, s->normal));
  if (const auto* s = std::get_if<BoundedPlane>(&shape))
    return std::max(0.0, -glm::dot(v, s->normal));
  if (const auto* s = std::get_if<Capsule>(&shape)) {
    const Vec3 ab = s->b - s->a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0 ? glm::dot(p - s->a, ab) / len2 : 0.0;
    if (t > 0 && t < 1) return glm::length(v - glm::dot(v, ab) / len2 * ab);
  }
  return glm::length(v);
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

}  // namespace

double free_acceleration(const State& state, const ContactCache& cache, int i) {
  const double g = cache.gravity;
  if (state.rolling(i)) return cache.collider_material[state.rolling_on[i]]->rolling_resistance * g;
  if (state.sliding(i)) {
    const ContactMaterial& m = *cache.collider_material[state.sliding_on[i]];
    return (m.friction + m.rolling_resistance) * g;
  }
  return 2.0 * g;
}

double collider_contact_time(const Model& model, const State& state, const double* x, int i, double horizon,
                             const ContactCache& cache, StepContacts* step) {
  const double margin = model.options.contact_margin;
  const Vec3 p = position(x, i), v = velocity(x, i);
  const double s = glm::length(v), a = free_acceleration(state, cache, i);
  double best = std::numeric_limits<double>::infinity();
  // Colliders farther than the ball can travel within the horizon cannot limit the step.
  const double travel = s * horizon + a * horizon * horizon + margin;
  near_colliders(model, cache, p, model.balls[i].radius, travel, [&](int c, const Penetration& pen) {
    if (pen.depth <= 0) {
      const double t = closing_time(margin - pen.depth, collider_closing_speed(model.colliders[c].shape, p, v), a);
      best = std::min(best, t);
      if (step && pen.depth <= -kTouch && t <= horizon) step->separated.emplace_back(i, -1 - c);
    }
    if (!step) return;
    if (begins(pen.depth, -glm::dot(v, pen.normal)))
      note_onset(*step, *cache.collider_material[c], -glm::dot(v, pen.normal), cache.inv_mass[i]);
    if (may_release(*cache.collider_material[c], pen.depth, -glm::dot(v, pen.normal))) step->pushing.emplace_back(i, -1 - c);
  });
  // A ball in the rolling or sliding regime ignores its support's geometry: it must not move far over a pocket's edge.
  const int bed = state.rolling(i) ? state.rolling_on[i] : state.sliding(i) ? state.sliding_on[i] : -1;
  if (bed >= 0) best = std::min(best, closing_time(hole_gap(model.colliders[bed].shape, p) + margin, s, a));
  return best;
}

double time_to_possible_contact(const Model& model, const State& state, const double* x, double horizon,
                                ContactCache& cache, StepContacts* step) {
  if (step) {  // every field reset, the lists keeping their storage
    *step = StepContacts{.separated = std::move(step->separated), .pushing = std::move(step->pushing),
                         .near = std::move(step->near)};
    step->separated.clear(), step->pushing.clear(), step->near.clear();
  }
  // Relative acceleration bound outside contacts: gravity plus cloth friction, generously twice |g|. A pair pushed
  // harder by third balls may start touching inside a step; the simulation then cuts the step at the onset.
  const double a_free = 2.0 * cache.gravity;
  auto accel = [&](int i) { return free_acceleration(state, cache, i); };
  const double margin = model.options.contact_margin;
  double best = std::numeric_limits<double>::infinity();
  double vmax = 0;
  const int n = state.ball_count();
  for (int i = 0; i < n; ++i) {
    if (!state.active(i)) continue;  // a sleeping ball does not move towards anything
    vmax = std::max(vmax, glm::length(velocity(x, i)));
    best = std::min(best, collider_contact_time(model, state, x, i, horizon, cache, step));
  }
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
  const double reach = 2.0 * vmax * h + a_free * h * h;
  sweep_pairs(model, state, x, cache, reach, false, [&](int i, int j) {
    const double ai = accel(i), aj = accel(j), a = ai == a_free || aj == a_free ? a_free : ai + aj;
    const Vec3 d0 = position(x, i) - position(x, j), v = velocity(x, i) - velocity(x, j);
    const double ri = model.balls[i].radius, rj = model.balls[j].radius, dist = glm::length(d0);
    const double closing = -glm::dot(v, d0) / dist;  // m/s
    if (step && begins(ri + rj - dist, closing))
      note_onset(*step, *cache.ball_ball, closing, std::max(cache.inv_mass[i], cache.inv_mass[j]));
    if (dist <= ri + rj) {  // already touching: the contact force is resolved by error control
      if (!step) return;
      step->near.emplace_back(i, j);
      if (may_release(*cache.ball_ball, ri + rj - dist, closing))
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
