// Sleep (regimes.hpp): which balls rest, and the groups of touching balls that fall asleep or wake together.
#include <cmath>

#include "events.hpp"
#include "regimes.hpp"

namespace shotlab {

bool Regimes::at_rest(const State& state, const StateVector& x, int i) const {
  const double eps = model_.options.rest_speed, r = model_.balls[i].radius;
  return glm::length(velocity(x, i)) < eps && r * glm::length(spin(x, i)) < eps &&
         ((classify(model_, index_, state, x.data(), i) == Motion::Stationary && !unbalanced(x, i)) ||
          held_still(x, i));
}

bool Regimes::unbalanced(const StateVector& x, int i) const {
  const BallSpec& b = model_.balls[i];
  const Vec3 p = position(x, i);
  Vec3 force = b.mass * model_.options.gravity;
  auto push = [&](const ContactMaterial& m, double depth, const Vec3& normal) {
    if (depth > 0) force += m.stiffness * std::pow(depth, m.exponent) * normal;
  };
  for (int j : touching_[i]) {
    const Vec3 d = p - position(x, j);
    const double len = glm::length(d);
    if (len > 0) push(index_.ball_ball(), b.radius + model_.balls[j].radius - len, d / len);
  }
  near_colliders(model_, index_, p, b.radius, 0.0,
                 [&](int c, const Penetration& pen) { push(index_.collider_material(c), pen.depth, pen.normal); });
  return glm::length(force) / b.mass * model_.options.sleep_time >= model_.options.rest_speed;
}

bool Regimes::held_still(const StateVector& x, int i) const {
  const Rod* held = nullptr;
  for (const Rod& rod : model_.rods)
    if (rod.ball == i) {
      if (held) return false;  // two rods: their forces are not the one-rod law below
      held = &rod;
    }
  // Pressed by nothing (a contact's force is not part of the balance below); a cradle's balls may touch at zero depth.
  const double r = model_.balls[i].radius;
  const Vec3 p = position(x, i);
  for (int j : touching_[i])
    if (glm::length(p - position(x, j)) - r - model_.balls[j].radius < 0) return false;
  bool pressed = false;
  near_colliders(model_, index_, p, r, 0.0, [&](int, const Penetration& pen) { pressed = pressed || pen.depth > 0; });
  if (pressed) return false;
  // What is left at zero speed: gravity, less what the rod (dynamics.cpp) takes along d^ (plus its length
  // correction, nil at the rod's length). Hanging below the anchor or level with it (g.d^ >= 0: above it the balance
  // is unstable), with what is left under rest_speed / sleep_time, the ball would not reach rest_speed in the
  // sleep_time that sleep asks it to rest. Without a rod that is a ball in free space without gravity.
  Vec3 a = model_.options.gravity;
  if (held) {
    const Vec3 d = p - held->anchor;
    const double len = glm::length(d);
    if (len <= 0 || std::abs(len - held->length) > model_.options.contact_margin) return false;
    const Vec3 dh = d / len;
    if (glm::dot(a, dh) < 0) return false;
    a -= glm::dot(a, dh) * dh;
  }
  return glm::length(a) * model_.options.sleep_time < model_.options.rest_speed;
}

bool Regimes::frozen_touch(const StateVector& x, int i, int j) const {
  return glm::length(position(x, i) - position(x, j)) - model_.balls[i].radius - model_.balls[j].radius < kTouch;
}

bool Regimes::update_sleep(State& state, StateVector& x, double dt) {
  if (model_.options.sleep_time <= 0) return false;
  resting_.assign(state.ball_count(), 0);
  for (int i = 0; i < state.ball_count(); ++i) {
    if (!state.in_play[i]) continue;
    resting_[i] = state.sleeping(i) || at_rest(state, x, i);
    state.still_for[i] = resting_[i] && !state.sleeping(i) ? state.still_for[i] + dt : 0.0;
  }
  const bool woke = wake_touched(state, x);
  const bool slept = sleep_rested(state, x);
  return woke || slept;
}

// Wake: flood from every awake ball that is moving through the touching graph; every sleeper reached wakes. A moving
// ball wakes a sleeper already within contact_margin, so that the sleeper is awake before the contact force builds up
// (steps end at contact onsets); sleepers wake each other only when frozen together.
bool Regimes::wake_touched(State& state, const StateVector& x) {
  const int n = state.ball_count();
  bool changed = false;
  stack_.clear();
  for (int i = 0; i < n; ++i)
    if (state.in_play[i] && !resting_[i]) stack_.push_back(i);
  seen_.assign(n, 0);
  while (!stack_.empty()) {
    const int i = stack_.back();
    stack_.pop_back();
    auto wake = [&](int j) {
      if (!state.sleeping(j) || seen_[j]) return;
      seen_[j] = 1;
      state.asleep[j] = 0;
      state.still_for[j] = 0;
      changed = true;
      stack_.push_back(j);
    };
    for (int j : touching_[i])
      if (!resting_[i]) wake(j);
    // touching_ leaves out sleeper pairs (the broad phase skips them); look those up directly.
    sleepers_near(model_, index_, x.data(), broad_, i, kTouch, [&](int j) {
      if (frozen_touch(x, i, j)) wake(j);
    });
  }
  return changed;
}

// Sleep: a group of touching awake balls falls asleep together once every one has rested for sleep_time.
bool Regimes::sleep_rested(State& state, StateVector& x) {
  bool changed = false;
  std::fill(seen_.begin(), seen_.end(), 0);
  for (int start = 0; start < state.ball_count(); ++start) {
    if (!state.active(start) || seen_[start]) continue;
    group_.assign(1, start);
    seen_[start] = 1;
    bool ready = true;
    for (size_t k = 0; k < group_.size(); ++k) {
      const int i = group_[k];
      ready = ready && state.still_for[i] >= model_.options.sleep_time;
      for (int j : touching_[i])
        if (state.active(j) && !seen_[j] && frozen_touch(x, i, j)) {
          seen_[j] = 1;
          group_.push_back(j);
        }
    }
    if (!ready) continue;
    for (int i : group_) {
      state.asleep[i] = 1;
      state.rolling_on[i] = -1;
      state.sliding_on[i] = -1;
      set_velocity(x, i, Vec3{0.0});
      set_spin(x, i, Vec3{0.0});
    }
    changed = true;
  }
  return changed;
}

}  // namespace shotlab
