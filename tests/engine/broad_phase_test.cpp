// The broad phases (engine/contacts.hpp, sweep_pairs; engine/model_index.hpp, ColliderGrid): whatever way they sort
// the balls or the colliders, every pair of balls that comes within the reach of each other, and every collider whose
// bounds a ball's reach touches, must be among the candidates, or a contact is missed. Checked against all of them.
#include <cmath>
#include <limits>
#include <random>
#include <set>

#include "engine/contacts.hpp"
#include "shotlab/scene.hpp"
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

// Balls at random over and around the colliders' extent, with reaches from none to half a table: each collider that
// Bounds::may_touch accepts must be visited, once, in ascending order. Returns how many queries the grid answered
// (the others are too wide, and the caller probes every collider) in `answered`, and how many colliders a query of a
// step's reach (1 cm at most) visits on average in `visited`.
void expect_grid_finds_every_collider(const ModelIndex& index, unsigned seed, int& answered, double& visited) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-1.8, 1.8), y(-0.1, 0.2), z(-1.0, 1.0), share(0.0, 1.0);
  const double reaches[] = {0.0, 0.001, 0.01, 0.05, 0.2, 1.0};
  answered = 0;
  int short_queries = 0;
  visited = 0;
  for (int q = 0; q < 20000; ++q) {
    const Vec3 p{x(rng), y(rng), z(rng)};
    const double reach = reaches[q % 6] * share(rng);
    std::vector<int> seen;
    if (!index.grid.visit(p, reach, [&](int k) { seen.push_back(k); })) {
      EXPECT_TRUE(seen.empty()) << "a query too wide for the grid visits nothing";
      continue;
    }
    ++answered;
    if (reach <= 0.01) ++short_queries, visited += static_cast<double>(seen.size());
    for (size_t n = 1; n < seen.size(); ++n) ASSERT_LT(seen[n - 1], seen[n]) << "visited out of order or twice";
    for (size_t k = 0; k < index.others.size(); ++k) {
      if (!index.collider_bounds[index.others[k]].may_touch(p, reach)) continue;
      ASSERT_TRUE(std::binary_search(seen.begin(), seen.end(), static_cast<int>(k)))
          << "collider " << index.others[k] << " missed at (" << p.x << ", " << p.y << ", " << p.z << "), reach " << reach;
    }
  }
  visited /= std::max(short_queries, 1);
}

TEST(BroadPhase, ColliderGridFindsEveryCushionAndJaw) {
  const Prepared p = prepare(load_scene(preset("cut.json")));
  const ModelIndex index(p.model);
  ASSERT_GT(index.others.size(), 20u);  // cushions, jaws and pocket backs
  int answered = 0;
  double visited = 0;
  expect_grid_finds_every_collider(index, 5, answered, visited);
  EXPECT_GT(answered, 10000);
  EXPECT_LT(visited, 3.0) << "the grid should leave most of the " << index.others.size() << " colliders out";
  // A reach over half the table, or a position that is not finite: the caller probes them all.
  EXPECT_FALSE(index.grid.visit(Vec3{0.0}, 1.0, [](int) {}));
  EXPECT_FALSE(index.grid.visit(Vec3{std::nan(""), 0.0, 0.0}, 0.01, [](int) {}));
  EXPECT_FALSE(index.grid.visit(Vec3{0.0}, std::numeric_limits<double>::infinity(), [](int) {}));
}

// More colliders than one 64-bit mask holds: spheres of all sizes strewn over a field.
TEST(BroadPhase, ColliderGridFindsEveryOneOfManyColliders) {
  Model model = empty_model();
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> at(-1.5, 1.5), size(0.001, 0.3);
  for (int c = 0; c < 150; ++c)
    model.colliders.push_back({"sphere-" + std::to_string(c), StaticSphere{{at(rng), 0.0, 0.6 * at(rng)}, size(rng)},
                               kBallCushion});
  const ModelIndex index(model);
  ASSERT_EQ(index.grid.words, 3);
  int answered = 0;
  double visited = 0;
  expect_grid_finds_every_collider(index, 7, answered, visited);
  EXPECT_GT(answered, 10000);
  EXPECT_LT(visited, 0.25 * index.others.size()) << "the grid should leave most colliders out";
}

}  // namespace
}  // namespace shotlab::test
