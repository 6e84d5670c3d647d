// Template bodies of contacts.hpp; not for direct inclusion.
#pragma once
#include <algorithm>
#include <cmath>

namespace shotlab {

void refresh_sleepers(const Model& model, const State& state, const double* x, BroadPhase& broad);  // contacts.cpp

template <class Fn>
void sleepers_near(const Model& model, const ModelIndex& index, const double* x, const BroadPhase& broad, int i,
                   double reach, Fn&& fn) {
  const double left = x[9 * i] - model.balls[i].radius - reach, right = x[9 * i] + model.balls[i].radius + reach;
  // Sleepers starting left of `right`, walked back while they may still reach `left` (extent at most 2 max_radius).
  auto k = std::lower_bound(broad.sleeper_left.begin(), broad.sleeper_left.end(), right) - broad.sleeper_left.begin();
  for (--k; k >= 0 && broad.sleeper_left[k] + 2 * index.max_radius > left; --k)
    if (broad.sleepers[k] != i) fn(broad.sleepers[k]);
}

// The awake balls in strips along z, each strip sorted by x and swept alone and against the next one: two balls whose
// z extents come within `reach` lie in the same strip or in neighbouring ones (a strip is at least 2 max_radius +
// reach high). A ball then meets the balls around it, not the whole strip across the field that its x extent cuts:
// on balls spread over an area the sweep along x alone finds about 0.3 sqrt(n) candidates a ball. False when a
// position or the field's extent is not finite (the plain sweep then takes over).
template <class Fn>
bool sweep_strips(const Model& model, const ModelIndex& index, const double* x, BroadPhase& broad, double reach,
                  Fn&& fn) {
  const std::vector<int>& awake = broad.awake;
  auto left = [&](int i) { return x[9 * i] - model.balls[i].radius; };
  auto width = [&](int i) { return 2 * model.balls[i].radius + reach; };  // of the extent, reach included
  double lo = x[9 * awake[0] + 2], hi = lo;
  for (int i : awake) {
    if (!std::isfinite(x[9 * i + 2]) || !std::isfinite(x[9 * i])) return false;
    lo = std::min(lo, x[9 * i + 2]), hi = std::max(hi, x[9 * i + 2]);
  }
  if (!std::isfinite(hi - lo)) return false;
  // No more strips than balls, however far apart they are.
  const double height = std::max(2 * index.max_radius + reach, (hi - lo) / static_cast<double>(awake.size()));
  auto strip = [&](int i) { return static_cast<size_t>((x[9 * i + 2] - lo) / height); };
  const size_t strips = static_cast<size_t>((hi - lo) / height) + 1;
  std::vector<int> &start = broad.strip_start, &order = broad.strip_order, &fill = broad.strip_fill;
  start.assign(strips + 1, 0);
  for (int i : awake) ++start[strip(i) + 1];
  for (size_t k = 0; k < strips; ++k) start[k + 1] += start[k];
  fill.assign(start.begin(), start.end() - 1);
  order.resize(awake.size());
  for (int i : awake) order[fill[strip(i)]++] = i;
  for (size_t k = 0; k < strips; ++k)
    std::sort(order.begin() + start[k], order.begin() + start[k + 1], [&](int a, int b) { return left(a) < left(b); });
  for (size_t k = 0; k < strips; ++k) {
    for (int a = start[k]; a < start[k + 1]; ++a) {
      const double right = left(order[a]) + width(order[a]);
      for (int b = a + 1; b < start[k + 1] && left(order[b]) < right; ++b) fn(order[a], order[b]);
    }
    if (k + 1 == strips) break;
    // Against the next strip: extents overlapping either way round. Its balls that end left of this ball's start end
    // left of every later one's too.
    int from = start[k + 1];
    for (int a = start[k]; a < start[k + 1]; ++a) {
      const double la = left(order[a]), right = la + width(order[a]);
      while (from < start[k + 2] && left(order[from]) + 2 * index.max_radius + reach <= la) ++from;
      for (int b = from; b < start[k + 2] && left(order[b]) < right; ++b)
        if (left(order[b]) + width(order[b]) > la) fn(order[a], order[b]);
    }
  }
  return true;
}

template <class Fn>
void sweep_pairs(const Model& model, const ModelIndex& index, const State& state, const double* x, BroadPhase& broad,
                 double reach, bool sleeping_pairs, Fn&& fn, const std::vector<int>* awake) {
  // Most islands are a lone ball, and every step runs several broad phases.
  if (state.ball_count() < 2) return;
  refresh_sleepers(model, state, x, broad);
  auto left = [&](int i) { return x[9 * i] - model.balls[i].radius; };
  auto sweep = [&](const std::vector<int>& order) {
    for (size_t a = 0; a < order.size(); ++a) {
      const double right = left(order[a]) + 2 * model.balls[order[a]].radius + reach;
      for (size_t b = a + 1; b < order.size() && left(order[b]) < right; ++b) fn(order[a], order[b]);
    }
  };
  if (awake) {
    broad.awake = *awake;
  } else {
    broad.awake.clear();
    for (int i = 0; i < state.ball_count(); ++i)
      if (state.active(i)) broad.awake.push_back(i);
  }
  // A few dozen awake balls (a rack, an island) sweep along x; more go in strips.
  constexpr size_t kStripsFrom = 64;
  if (broad.awake.size() < kStripsFrom || !sweep_strips(model, index, x, broad, reach, fn)) {
    std::sort(broad.awake.begin(), broad.awake.end(), [&](int a, int b) { return left(a) < left(b); });
    sweep(broad.awake);
  }
  if (!broad.sleepers.empty())
    for (int i : broad.awake) sleepers_near(model, index, x, broad, i, reach, [&](int j) { fn(i, j); });
  if (sleeping_pairs) sweep(broad.sleepers);
}

template <class Fn>
void near_collider(const Model& model, const ModelIndex& index, int c, const Vec3& p, double r, double within, Fn&& fn) {
  const double reach = r + within;
  if (index.floor_of[c] >= 0) {  // plane-like: over its level floor by one subtraction
    const auto on_floor = floor_penetration(index, static_cast<size_t>(index.floor_of[c]), p, r);
    if (on_floor) {
      if (*on_floor && index.collider_bounds[c].may_touch(p, reach)) fn(c, **on_floor);
      return;
    }
  }
  if (!index.collider_bounds[c].may_touch(p, reach)) return;
  if (const auto pen = penetration(model.colliders[c].shape, p, r, within)) fn(c, *pen);
}

template <class Fn>
void near_colliders(const Model& model, const ModelIndex& index, const Vec3& p, double r, double within, Fn&& fn) {
  for (const int c : index.plane_like) near_collider(model, index, c, p, r, within, fn);
  // Inside the clear column nothing else can be in reach. Elsewhere probe the colliders the grid finds in reach, or
  // every one where it declines.
  const double reach = r + within;
  if (index.clear.holds(p, reach)) return;
  if (!index.grid.visit(p, reach, [&](int k) { near_collider(model, index, index.others[k], p, r, within, fn); }))
    for (int c : index.others) near_collider(model, index, c, p, r, within, fn);
}

template <class Fn>
void for_each_contact(const Model& model, const ModelIndex& index, const State& state, const double* x,
                      BroadPhase& broad, const StepContacts* plan, Fn&& fn, bool with_inactive, bool inner_stage) {
  const StepContacts& step = plan ? *plan : kNoPlan;
  const Smoothing k{model.options.friction_sharpness, model.options.friction_rate_limit};
  const int n = state.ball_count();
  auto listed = [](const std::vector<ContactKey>& keys, int a, int b) {
    return !keys.empty() && std::binary_search(keys.begin(), keys.end(), ContactKey{a, b});
  };
  // Ball against static colliders: B has zero velocity.
  const bool colliders_known = step.colliders_known && !with_inactive && inner_stage;
  for (int i = 0; i < n; ++i) {
    if (!state.in_play[i] || ((state.sleeping(i) || state.rolling(i) || state.sliding(i)) && !with_inactive)) continue;
    const double r = model.balls[i].radius;
    const Vec3 p = position(x, i), v = velocity(x, i), w = spin(x, i);
    auto touching = [&](int c, const Penetration& pen) {
      if (pen.depth <= 0 || listed(step.separated, i, -1 - c)) return;
      const ContactForce f = collider_force(index.collider_material(c), index, i, r, v, w, pen, k,
                                            !listed(step.pushing, i, -1 - c));
      fn(Contact{i, -1, c, pen.depth, pen.normal, p - r * pen.normal, f});
    };
    if (!colliders_known) {
      near_colliders(model, index, p, r, 0.0, touching);
      continue;
    }
    for (int l = step.collider_from[i]; l < step.collider_from[i + 1]; ++l)
      near_collider(model, index, step.colliders[l], p, r, 0.0, touching);
  }
  // Ball against ball: n points from j to i; A's contact point is at -R_i n, B's at +R_j n.
  const bool near_known = step.near_known && !with_inactive;
  if (!near_known) overlapping_pairs(model, index, state, x, broad, 0.0, with_inactive);
  const ContactMaterial& bb = index.ball_ball();
  for (const auto& [i, j] : near_known ? step.near : broad.pairs) {
    const int a = std::min(i, j), b = std::max(i, j);
    // The step's near pairs hold no two sleepers and none of its separated pairs, by construction (its cap sweeps with
    // no sleeper pairs, time_to_possible_contact; a change of who sleeps makes the next step's lists or a sweep).
    if (!near_known && ((state.sleeping(i) && state.sleeping(j) && !with_inactive) || listed(step.separated, a, b)))
      continue;
    const double ri = model.balls[i].radius, rj = model.balls[j].radius;
    if (near_known) {
      const Vec3 d = position(x, i) - position(x, j);
      if (glm::dot(d, d) >= (ri + rj) * (ri + rj) || !state.in_play[i] || !state.in_play[j]) continue;
    }
    const ContactKinematics kin = pair_kinematics(model, index, x, i, j);
    fn(Contact{i, j, -1, kin.depth, kin.normal, position(x, i) - ri * kin.normal,
               contact_force(bb, kin, k, !listed(step.pushing, a, b))});
  }
}

}  // namespace shotlab
