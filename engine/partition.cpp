#include "partition.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace shotlab {

int Partitioner::root(int i) {
  while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
  return i;
}

void Partitioner::join(int i, int j) {
  i = root(i);
  j = root(j);
  if (i == j) return;
  if (j < i) std::swap(i, j);
  parent_[j] = i;
  energy_[i] += energy_[j];
  joined_ = true;
}

double Partitioner::speed_bound(double e, int i) const {
  // On a table the height a ball can fall is in its energy; elsewhere gravity adds up to g h within the horizon (an
  // island lives at most kMaxHorizon off a table).
  const double fall = model_.balls_leave_below_bed ? 0.0 : glm::length(model_.options.gravity) * kMaxHorizon;
  return std::sqrt(2.0 * e / model_.balls[i].mass) + fall;
}

void Partitioner::join_sleeper(int i, int sleeper, const State& state) {
  if (root(i) == root(sleeper)) return;
  // A sleeper already reached (by another island, or earlier) brings its frozen group with it.
  if (reached_[sleeper]) return join(i, sleeper);
  const double* x = state.x.data();
  std::vector<int> group{sleeper};
  reached_[sleeper] = 1;
  woken_.push_back(sleeper);
  for (size_t k = 0; k < group.size(); ++k) {
    const int s = group[k];
    join(i, s);
    sleepers_near(model_, index_, x, broad_, s, kTouch, [&](int j) {
      if (reached_[j]) return;
      const double gap = glm::length(position(x, s) - position(x, j)) - model_.balls[s].radius - model_.balls[j].radius;
      if (gap < kTouch) {
        reached_[j] = 1;
        woken_.push_back(j);
        group.push_back(j);
      }
    });
  }
}

// The union-find arrays are as long as the scene; only the entries of awake balls and reached sleepers are used, and
// only those are reset afterwards (reset), so that a partition costs O(awake), not O(balls).
Partition Partitioner::operator()(const State& state, const std::vector<int>& awake) {
  size_for(state.ball_count());
  add_energies(state, awake);
  link(state, awake);
  std::vector<int> members(awake);
  members.insert(members.end(), woken_.begin(), woken_.end());
  std::sort(members.begin(), members.end());
  Partition p = collect(members);
  set_horizons(state, awake, p);
  reset(members);
  return p;
}

void Partitioner::size_for(int n) {
  if (parent_.size() == static_cast<size_t>(n)) return;
  parent_.resize(n);
  std::iota(parent_.begin(), parent_.end(), 0);
  energy_.assign(n, 0.0);
  reached_.assign(n, 0);
  slot_.assign(n, -1);
  path_.assign(n, std::nullopt);
  path_found_.assign(n, 0);
}

// Each awake ball's energy: kinetic, the height above the bed it can still fall (tables only: elsewhere free fall is
// covered by g h), and the elastic energy of its contacts (a compressed contact gives it back as speed).
void Partitioner::add_energies(const State& state, const std::vector<int>& awake) {
  const double* x = state.x.data();
  const double g = glm::length(model_.options.gravity);
  for (int i : awake) {
    const BallSpec& b = model_.balls[i];
    const Vec3 v = velocity(x, i), w = spin(x, i);
    energy_[i] = 0.5 * b.mass * glm::dot(v, v) + 0.5 * b.inertia() * glm::dot(w, w);
    if (model_.balls_leave_below_bed) energy_[i] += b.mass * g * std::max(0.0, x[9 * i + 1] - b.radius);
    if (!state.rolling(i) && !state.sliding(i))  // the bed contact of a rolling or sliding ball is its static sink
      near_colliders(model_, index_, position(x, i), b.radius, 0.0, [&](int c, const Penetration& pen) {
        if (pen.depth > 0) energy_[i] += elastic_energy(index_.collider_material(c), pen.depth);
      });
  }
  sweep_pairs(model_, index_, state, x, broad_, 0.0, false, [&](int i, int j) {
    const double depth = model_.balls[i].radius + model_.balls[j].radius - glm::length(position(x, i) - position(x, j));
    if (depth <= 0) return;
    for (int k : {i, j})  // a sleeper's share would stay behind in its entry: the awake one holds the pair's
      if (!state.sleeping(k)) energy_[k] += elastic_energy(index_.ball_ball(), depth);
  }, &awake);
}

// m/s: how fast ball i may move. A sleeper that an island may reach can be woken and hit within the horizon: it moves
// as the island's balls may.
double Partitioner::speed(const State& state, int i) { return state.sleeping(i) && !reached_[i] ? 0.0 : bound(i); }

// Calls fn(i, j, gap, closing) for the pairs (at least one that may move) whose x extents come within what they can
// close in `time`: gap (m, beyond contact_margin) and the bound on how fast they can close it.
template <class Fn>
void Partitioner::near_pairs(const State& state, const std::vector<int>& awake, double time, Fn&& fn) {
  const double* x = state.x.data();
  const double margin = model_.options.contact_margin;
  double vmax = 0;
  for (int i : awake) vmax = std::max(vmax, bound(i));
  for (int i : woken_) vmax = std::max(vmax, bound(i));
  const double reach = 2.0 * vmax * time + margin;
  auto visit = [&](int i, int j) {
    const double gap =
        glm::length(position(x, i) - position(x, j)) - model_.balls[i].radius - model_.balls[j].radius - margin;
    fn(i, j, gap, speed(state, i) + speed(state, j));
  };
  sweep_pairs(model_, index_, state, x, broad_, reach, false, visit, &awake);
  // sweep_pairs leaves out pairs of sleepers: those of a reached one matter.
  for (size_t k = 0; k < woken_.size(); ++k) {
    const int s = woken_[k];
    sleepers_near(model_, index_, x, broad_, s, reach, [&](int j) { visit(s, j); });
  }
}

// Joins the balls that could touch within kLinkTime, until no join is left: joins raise energies, and with them the
// reach of every member.
void Partitioner::link(const State& state, const std::vector<int>& awake) {
  do {
    joined_ = false;
    near_pairs(state, awake, kLinkTime, [&](int i, int j, double gap, double closing) {
      if (gap >= closing * kLinkTime) return;
      if (state.sleeping(j) && !reached_[j]) join_sleeper(i, j, state);
      else if (state.sleeping(i) && !reached_[i]) join_sleeper(j, i, state);
      else join(i, j);
    });
  } while (joined_);
}

// The islands of the members (awake balls and reached sleepers, ascending), in the order of their first ball.
Partition Partitioner::collect(const std::vector<int>& members) {
  Partition p;
  for (int i : members) {
    int& s = slot_[root(i)];
    if (s < 0) {
      s = static_cast<int>(p.islands.size());
      p.islands.emplace_back();
      p.energy.push_back(energy_[root(i)]);
    }
    p.islands[s].push_back(i);
  }
  return p;
}

// Horizons: a lone ball on a table has nothing to split off (a reached sleeper may wake and need splitting off), so it
// runs longer; then the earliest time each island could touch another's ball or a sleeper it does not hold.
void Partitioner::set_horizons(const State& state, const std::vector<int>& awake, Partition& p) {
  for (const auto& island : p.islands)
    p.horizon.push_back(model_.balls_leave_below_bed && island.size() == 1 && !reached_[island[0]] ? kLoneHorizon
                                                                                                    : kMaxHorizon);
  const double margin = model_.options.contact_margin;
  auto horizon = [&](int i) { return slot_[root(i)] >= 0 ? p.horizon[slot_[root(i)]] : 0.0; };
  near_pairs(state, awake, kLoneHorizon, [&](int i, int j, double gap, double closing) {
    if (root(i) == root(j) || closing <= 0) return;
    double h = std::max(gap, 0.0) / closing;
    if (h < std::max(horizon(i), horizon(j)) && path(state, p, i) && path(state, p, j))  // where the bound would be
      h = std::max(h, path_meeting_time(*path(state, p, i), *path(state, p, j),       // the horizon only
                                        model_.balls[i].radius + model_.balls[j].radius + margin, closing));
    for (int k : {i, j})
      if (slot_[root(k)] >= 0) p.horizon[slot_[root(k)]] = std::min(p.horizon[slot_[root(k)]], h);
  });
}

// The free path of a lone ball or a sleeper, found when first needed (path_found_).
const std::optional<FreePath>& Partitioner::path(const State& state, const Partition& p, int i) {
  if (!path_found_[i]) {
    path_found_[i] = 1;
    const int s = slot_[root(i)];
    const bool lone = s >= 0 ? p.islands[s].size() == 1 && !reached_[i] : state.sleeping(i);
    path_[i] = lone ? free_path(model_, state, state.x.data(), i, index_, kLoneHorizon) : std::nullopt;
    if (s < 0) found_.push_back(i);  // a sleeper: not among the members reset below
  }
  return path_[i];
}

void Partitioner::reset(const std::vector<int>& members) {
  for (int i : members) {
    slot_[i] = -1;
    path_found_[i] = 0;
    parent_[i] = i;
    energy_[i] = 0;
    reached_[i] = 0;
  }
  woken_.clear();
  for (int i : found_) path_found_[i] = 0;
  found_.clear();
}

}  // namespace shotlab
