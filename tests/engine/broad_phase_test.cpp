// The broad phase (engine/contacts.hpp, sweep_pairs): whatever way it sorts the balls, every pair of balls that comes
// within the reach of each other must be among its candidates, or a contact is missed. Checked against all pairs.
#include <random>
#include <set>

#include "engine/contacts.hpp"
#include "support.hpp"

namespace shotlab::test {
namespace {

// n balls at random over a field of the given side (m), some of them asleep; the pairs within `reach` of touching,
// found by testing every pair, must all be candidates of sweep_pairs (at most once each).
void expect_every_close_pair(int n, double side, double reach, unsigned seed) {
  Model model = empty_model();
  State state;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> at(-side / 2, side / 2), radius(0.02, 0.035);
  for (int i = 0; i < n; ++i) {
    model.balls.push_back({std::to_string(i), 0.17, radius(rng)});
    state.x.insert(state.x.end(), {at(rng), 0.0, at(rng), 0, 0, 0, 0, 0, 0});
  }
  state.in_play.assign(n, 1);
  state.asleep.assign(n, 0);
  for (int i = 0; i < n; i += 7) state.asleep[i] = 1;  // sleepers meet awake balls through their own list
  state.rolling_on.assign(n, -1);
  state.sliding_on.assign(n, -1);
  state.still_for.assign(n, 0.0);
  const ModelIndex index(model);
  BroadPhase broad;
  std::multiset<std::pair<int, int>> found;
  sweep_pairs(model, index, state, state.x.data(), broad, reach, false,
              [&](int i, int j) { found.insert({std::min(i, j), std::max(i, j)}); });
  int close = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if (state.asleep[i] && state.asleep[j]) continue;
      const double gap = glm::length(position(state.x, i) - position(state.x, j)) - model.balls[i].radius -
                         model.balls[j].radius;
      if (gap >= reach) continue;
      ++close;
      EXPECT_EQ(found.count({i, j}), 1u) << n << " balls: pair " << i << ", " << j << " (gap " << gap << " m) missed";
    }
  EXPECT_GT(close, n / 4) << "the field is too sparse to test anything";
}

TEST(BroadPhase, SweepFindsEveryCloseFewBalls) { expect_every_close_pair(40, 0.6, 0.01, 1); }

TEST(BroadPhase, StripsFindEveryCloseManyBalls) {
  expect_every_close_pair(500, 2.0, 0.01, 2);
  expect_every_close_pair(2000, 3.0, 0.05, 3);
  expect_every_close_pair(300, 0.5, 0.0, 4);  // dense: many pairs touch
}

}  // namespace
}  // namespace shotlab::test
