#include "sleep.hpp"

#include "events.hpp"

namespace shotlab {
namespace {
// Balls this close count as touching for waking and grouping: frozen balls touch at zero depth, give or take
// round-off.
constexpr double kTouchSlack = 1e-9;
}  // namespace

bool Sleep::at_rest(const State& state, const StateVector& x, int i) const {
  const double eps = model_.options.rest_speed, r = model_.balls[i].radius;
  return glm::length(velocity(x, i)) < eps && r * glm::length(spin(x, i)) < eps &&
         classify(model_, state, x.data(), i) == Motion::Stationary;
}

bool Sleep::update(State& state, StateVector& x, double dt) {
  const int n = state.ball_count();
  if (model_.options.sleep_time <= 0 || n == 0) return false;
  if (state.asleep.size() != static_cast<size_t>(n)) state.asleep.assign(n, 0);
  still_for_.resize(n, 0.0);
  touching_.assign(n, {});
  overlapping_pairs(model_, state, x.data(), cache_, kTouchSlack);
  for (const auto& [i, j] : cache_.pairs) {
    touching_[i].push_back(j);
    touching_[j].push_back(i);
  }
  std::vector<uint8_t> resting(n, 0);
  for (int i = 0; i < n; ++i) {
    if (!state.in_play[i]) continue;
    resting[i] = state.sleeping(i) || at_rest(state, x, i);
    still_for_[i] = resting[i] && !state.sleeping(i) ? still_for_[i] + dt : 0.0;
  }
  bool changed = false;
  // Wake: flood from every awake ball that is moving through the touching graph; every sleeper reached wakes.
  std::vector<int> stack;
  for (int i = 0; i < n; ++i)
    if (state.in_play[i] && !resting[i]) stack.push_back(i);
  std::vector<uint8_t> seen(n, 0);
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    for (int j : touching_[i])
      if (state.sleeping(j) && !seen[j]) {
        seen[j] = 1;
        state.asleep[j] = 0;
        still_for_[j] = 0;
        changed = true;
        stack.push_back(j);
      }
  }
  // Sleep: a group of touching awake balls falls asleep together once every one has rested for sleep_time.
  std::fill(seen.begin(), seen.end(), 0);
  for (int start = 0; start < n; ++start) {
    if (!state.active(start) || seen[start]) continue;
    std::vector<int> group{start};
    seen[start] = 1;
    bool ready = true;
    for (size_t k = 0; k < group.size(); ++k) {
      const int i = group[k];
      ready = ready && still_for_[i] >= model_.options.sleep_time;
      for (int j : touching_[i])
        if (state.active(j) && !seen[j]) {
          seen[j] = 1;
          group.push_back(j);
        }
    }
    if (!ready) continue;
    for (int i : group) {
      state.asleep[i] = 1;
      set_velocity(x, i, Vec3{0.0});
      set_spin(x, i, Vec3{0.0});
    }
    changed = true;
  }
  return changed;
}

}  // namespace shotlab
