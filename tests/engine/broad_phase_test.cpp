// The broad phases (engine/contacts.hpp, sweep_pairs; engine/model_index.hpp, ColliderGrid): whatever way they sort
// the balls or the colliders, every pair of balls that comes within the reach of each other, and every collider whose
// bounds a ball's reach touches, must be among the candidates, or a contact is missed. Checked against all of them.
#include <cmath>
#include <limits>
#include <utility>
#include <vector>
#include <random>
#include <set>

#include "engine/contacts.hpp"
#include "engine/dynamics.hpp"
#include "shotlab/io/scene_json.hpp"
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

// Whether the grid visits every collider that Bounds::may_touch accepts at p within reach, once each, in ascending
// order. False where the grid declines the query; `visited` gets how many it visited.
bool visits_every_collider_in_reach(const ModelIndex& index, const Vec3& p, double reach, size_t& visited) {
  std::vector<int> seen;
  visited = 0;
  if (!index.grid.visit(p, reach, [&](int k) { seen.push_back(k); })) {
    EXPECT_TRUE(seen.empty()) << "a declined query visits nothing";
    return false;
  }
  visited = seen.size();
  for (size_t n = 1; n < seen.size(); ++n) EXPECT_LT(seen[n - 1], seen[n]) << "visited out of order or twice";
  for (size_t k = 0; k < index.others.size(); ++k) {
    if (!index.collider_bounds[index.others[k]].may_touch(p, reach)) continue;
    EXPECT_TRUE(std::binary_search(seen.begin(), seen.end(), static_cast<int>(k)))
        << "collider " << index.others[k] << " missed at (" << p.x << ", " << p.y << ", " << p.z << "), reach "
        << reach;
  }
  return true;
}

// Balls at random over and around the colliders' extent, with reaches from none to half a table. Returns how many
// queries the grid answered (it declines the wider ones), and in `visited` how many colliders a query of a step's reach
// (1 cm at most) visits on average.
int expect_random_queries_find_every_collider(const ModelIndex& index, unsigned seed, double& visited) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-3.0, 3.0), y(-0.1, 0.2), z(-2.0, 2.0), share(0.0, 1.0);
  const double reaches[] = {0.0, 0.001, 0.01, 0.05, 0.2, 1.0};
  int answered = 0, short_queries = 0;
  visited = 0;
  for (int q = 0; q < 20000; ++q) {
    const double reach = reaches[q % 6] * share(rng);
    size_t n = 0;
    if (!visits_every_collider_in_reach(index, {x(rng), y(rng), z(rng)}, reach, n)) continue;
    ++answered;
    if (reach <= 0.01) ++short_queries, visited += static_cast<double>(n);
  }
  visited /= std::max(short_queries, 1);
  return answered;
}

// Each collider's own edges: a ball whose reach ends within a few ulps of the bounds, on either side, on each axis.
void expect_edges_found(const ModelIndex& index) {
  size_t n = 0;
  for (int c : index.others) {
    const Bounds& b = index.collider_bounds[c];
    const Vec3 mid = 0.5 * (b.lo + b.hi);
    for (const double reach : {0.0, 1e-3, 0.01})
      for (const double edge : {b.lo.x - reach, b.hi.x + reach, b.lo.z - reach, b.hi.z + reach}) {
        const bool along_x = edge == b.lo.x - reach || edge == b.hi.x + reach;
        double at = edge;
        for (int ulp = 0; ulp < 3; ++ulp) at = std::nextafter(at, -INFINITY);
        for (int ulp = 0; ulp < 6; ++ulp, at = std::nextafter(at, INFINITY))
          visits_every_collider_in_reach(index, along_x ? Vec3{at, mid.y, mid.z} : Vec3{mid.x, mid.y, at}, reach, n);
      }
  }
}

// near_colliders against the loop over every collider it replaced: the same contacts, the same depths, in the same
// order.
void expect_near_colliders_as_the_loop(const Model& model, const ModelIndex& index, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-1.6, 1.6), y(-0.05, 0.1), z(-0.9, 0.9), within(0.0, 0.05);
  for (int q = 0; q < 20000; ++q) {
    const Vec3 p{x(rng), y(rng), z(rng)};
    const double r = kR, w = q % 2 ? within(rng) : 0.0;
    std::vector<std::pair<int, double>> got, want;
    near_colliders(model, index, p, r, w, [&](int c, const Penetration& pen) {
      if (index.floor_of[c] < 0) got.emplace_back(c, pen.depth);
    });
    if (!index.clear.holds(p, r + w))
      for (int c : index.others)
        if (index.collider_bounds[c].may_touch(p, r + w))
          if (const auto pen = penetration(model.colliders[c].shape, p, r, w)) want.emplace_back(c, pen->depth);
    ASSERT_EQ(got, want) << "at (" << p.x << ", " << p.y << ", " << p.z << "), within " << w;
  }
}

TEST(BroadPhase, ColliderGridFindsEveryCushionAndJaw) {
  const Prepared p = prepare(load_scene(preset("cut.json")));
  const ModelIndex index(p.model);
  ASSERT_GT(index.others.size(), 20u);  // cushions, jaws and pocket backs
  double visited = 0;
  EXPECT_GT(expect_random_queries_find_every_collider(index, 5, visited), 10000);
  EXPECT_LT(visited, 3.0) << "the grid should leave most of the " << index.others.size() << " colliders out";
  expect_edges_found(index);
  expect_near_colliders_as_the_loop(p.model, index, 8);
  // A reach over half the table, a negative one, a position or reach that is not finite: the caller probes them all.
  for (const auto& [at, reach] : std::vector<std::pair<Vec3, double>>{{Vec3{0.0}, 1.0},
                                                                      {Vec3{1.27, 0.0, 0.0}, -0.01},
                                                                      {Vec3{std::nan(""), 0.0, 0.0}, 0.01},
                                                                      {Vec3{0.0, 0.0, std::nan("")}, 0.01},
                                                                      {Vec3{0.0}, std::nan("")},
                                                                      {Vec3{0.0}, INFINITY},
                                                                      {Vec3{1e308, 0.0, 0.0}, 1e308}})
    EXPECT_FALSE(index.grid.visit(at, reach, [](int) {})) << at.x << ", " << at.z << ", reach " << reach;
  // Far outside the extent the edge cells answer, and every collider there is out of reach.
  size_t n = 0;
  EXPECT_TRUE(visits_every_collider_in_reach(index, {1e6, 0.0, -1e6}, 0.01, n));
}

// More colliders than one 64-bit mask holds, and odd layouts: one collider, all of them at one point, one far away.
TEST(BroadPhase, ColliderGridFindsEveryOneOfManyColliders) {
  auto spheres = [](int count, double spread, double size, unsigned seed) {
    Model model = empty_model();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> at(-spread, spread), radius(0.001, size);
    for (int c = 0; c < count; ++c)
      model.colliders.push_back({"sphere-" + std::to_string(c),
                                 StaticSphere{{at(rng), 0.0, 0.6 * at(rng)}, radius(rng)}, kBallCushion});
    return model;
  };
  double visited = 0;
  const Model many = spheres(150, 1.5, 0.3, 6);
  const ModelIndex index(many);
  ASSERT_EQ(index.grid.words(), 3);
  EXPECT_GT(expect_random_queries_find_every_collider(index, 7, visited), 10000);
  EXPECT_LT(visited, 0.25 * static_cast<double>(index.others.size())) << "the grid should leave most colliders out";
  expect_edges_found(index);
  for (const Model& odd : {spheres(1, 1.0, 0.1, 9), spheres(40, 0.0, 1e-6, 10)}) {
    const ModelIndex one(odd);
    ASSERT_TRUE(one.grid.built());
    expect_random_queries_find_every_collider(one, 11, visited);
    expect_edges_found(one);
  }
  Model far = spheres(30, 1.0, 0.1, 12);
  far.colliders.push_back({"far", StaticSphere{{5e4, 0.0, -5e4}, 0.1}, kBallCushion});
  const ModelIndex far_index(far);
  expect_random_queries_find_every_collider(far_index, 13, visited);
  expect_edges_found(far_index);
  // A bound that is not finite: no grid (every query declined), as may_touch accepts nothing there.
  for (const Vec3& centre : {Vec3{std::nan(""), 0.0, 0.0}, Vec3{0.0, 0.0, std::nan("")}}) {
    Model broken = spheres(10, 1.0, 0.1, 14);
    broken.colliders.push_back({"nan", StaticSphere{centre, 0.1}, kBallCushion});
    EXPECT_FALSE(ModelIndex(broken).grid.built());
  }
}

// A step's plan lists each ball's colliders (StepContacts::colliders), and the stages of the step probe only those. Balls
// near the cushions, jaws and pockets of a pool table, moving at up to 3 m/s, each moved as a step of h could move
// it (gravity and cloth friction bound its acceleration by 2 g, free_acceleration): every collider contact found by
// probing every collider is found from the lists, with the same force to the bit, in the same order.
TEST(BroadPhase, AStepsCollidersHoldEveryContactItCouldMake) {
  Prepared p = prepare(load_scene(preset("break.json")));
  const Model& model = p.model;
  const ModelIndex index(model);
  State state = p.state;
  const int n = state.ball_count();
  state.asleep.assign(n, 0);  // every ball awake, in the full model
  state.rolling_on.assign(n, -1);
  state.sliding_on.assign(n, -1);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), share(0.0, 1.0);
  auto dir = [&] { return glm::normalize(Vec3{unit(rng), 0.3 * unit(rng), unit(rng)}); };
  // Near the rails: within 4 cm of the cushions' noses (1.27 m by 0.635 m from the centre), at and above the bed.
  auto near_rail = [&](double r) {
    const double x = share(rng) < 0.5 ? std::copysign(1.23 + 0.04 * share(rng), unit(rng)) : 1.27 * unit(rng);
    const double z = std::abs(x) < 1.23 ? std::copysign(0.595 + 0.04 * share(rng), unit(rng)) : 0.635 * unit(rng);
    return Vec3{x, r - 2e-6 + (share(rng) < 0.5 ? 0.0 : 2e-3 * share(rng)), z};
  };
  int contacts = 0, new_ones = 0;
  size_t listed = 0;
  for (int trial = 0; trial < 400; ++trial) {
    for (int i = 0; i < n; ++i) {
      const double r = model.balls[i].radius;
      set_position(state.x, i, near_rail(r));
      set_velocity(state.x, i, 3.0 * share(rng) * dir());
      set_spin(state.x, i, 50.0 * share(rng) * dir());
    }
    const double h = std::pow(10.0, -5.0 + 3.0 * share(rng));  // s: 10 us to 10 ms
    StepContacts plan;
    BroadPhase broad;
    time_to_possible_contact(model, index, state, state.x.data(), h, broad, &plan);
    ASSERT_TRUE(plan.colliders_known);
    listed += plan.colliders.size();
    plan.separated.clear();  // nothing left out of the step: the lists alone decide which colliders the stages see
    // Where the step could take them.
    StateVector moved = state.x;
    for (int i = 0; i < n; ++i) {
      const double t = h * share(rng);
      const Vec3 a = 2.0 * index.gravity * share(rng) * dir();
      set_position(moved, i, position(state.x, i) + velocity(state.x, i) * t + 0.5 * a * t * t);
    }
    auto collider_contacts = [&](const double* x, bool inner_stage) {
      std::vector<std::pair<int, double>> out;  // (collider, normal force) of each ball's contacts, in order
      BroadPhase b;
      for_each_contact(model, index, state, x, b, &plan, [&](const Contact& c) {
        if (c.other_ball < 0) out.emplace_back(c.ball * 1000 + c.collider, c.force.normal);
      }, false, inner_stage);
      return out;
    };
    const auto all = collider_contacts(moved.data(), false), from_lists = collider_contacts(moved.data(), true);
    EXPECT_EQ(from_lists, all) << "trial " << trial << ", h = " << h << " s";
    contacts += static_cast<int>(all.size());
    const auto before = collider_contacts(state.x.data(), false);
    for (const auto& c : all)
      new_ones += std::none_of(before.begin(), before.end(), [&](const auto& b) { return b.first == c.first; });
  }
  EXPECT_GT(new_ones, 100) << "too few contacts begin within the steps to test the lists";
  EXPECT_GT(contacts, 2000);
  // The lists leave most of the 25 colliders out: the bed and what is near.
  EXPECT_LT(static_cast<double>(listed) / (400.0 * n), 3.0);
}

// A ball that a step takes past its reach (pushed harder than the bound by the balls around it) meets a collider that
// the plan did not list: the stages do not see it, the evaluation that records a trial's end does, so that the event
// detector finds the onset and ends the step there.
TEST(BroadPhase, TheRecordingEvaluationSeesAnUnlistedCollider) {
  Prepared p = prepare(load_scene(preset("cut.json")));
  const ModelIndex index(p.model);
  State& state = p.state;
  const double r = p.model.balls[0].radius;
  set_position(state.x, 0, Vec3{1.27 - r - 0.01, r - 2e-6, 0.1});  // 1 cm short of the right cushion, at rest
  set_velocity(state.x, 0, Vec3{0.0});
  set_spin(state.x, 0, Vec3{0.0});
  StepContacts plan;
  BroadPhase broad;
  time_to_possible_contact(p.model, index, state, state.x.data(), 1e-4, broad, &plan);
  StateVector pushed = state.x;
  set_position(pushed, 0, Vec3{1.246, r - 2e-6, 0.1});  // 3 mm into it
  Dynamics f(p.model, index, state);
  f.swap_plan(plan);
  StateVector dxdt;
  auto touches_cushion = [&] {
    return std::any_of(f.recorded().begin(), f.recorded().end(),
                       [](const ContactRecord& c) { return c.key.first == 0 && c.key.second < 0 && c.normal > 100.0; });
  };
  f.set_recording(true);
  f(pushed, dxdt, 0.0);
  EXPECT_TRUE(touches_cushion());
  EXPECT_LT(dxdt[3], -100.0) << "the cushion pushes the ball back";
  f.set_recording(false);
  f(pushed, dxdt, 0.0);
  EXPECT_GT(dxdt[3], -1.0) << "an inner stage probes the listed colliders only";
}

}  // namespace
}  // namespace shotlab::test
