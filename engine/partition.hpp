// Splitting a scene into islands (island.hpp) that cannot touch each other before a horizon, so that each integrates
// on its own with its own step size: Box2D's islands, made time-aware by a bound on each ball's speed from its
// island's energy and by the known free paths of lone balls and sleepers (docs/model.md#islands).
#pragma once
#include <optional>
#include <vector>

#include "contacts.hpp"
#include "shotlab/model.hpp"
#include "free_path.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

struct Partition {
  std::vector<std::vector<int>> islands;  // ball indices, ascending; islands ordered by their first ball
  std::vector<double> energy;             // J, each island's: the bound on what its balls can gain
  std::vector<double> horizon;            // s from the state's time, each island's: it touches nothing else before
};

class Partitioner {
 public:
  Partitioner(const Model& model, const ModelIndex& index) : model_(model), index_(index) {}
  // Islands of the awake balls in play, `awake` (with the sleepers they may reach); balls out of play and sleepers
  // nothing can reach are in none.
  Partition operator()(const State& state, const std::vector<int>& awake);
  // m/s: how fast ball i of an island with energy e (J) can move, at most (V_i above).
  double speed_bound(double e, int i) const;

 private:
  int root(int i);
  void join(int i, int j);
  void join_sleeper(int i, int sleeper, const State& state);  // with every sleeper frozen against it
  double bound(int i) { return speed_bound(energy_[root(i)], i); }
  // The stages of operator(), in order.
  void size_for(int n);
  void add_energies(const State& state, const std::vector<int>& awake);
  void link(const State& state, const std::vector<int>& awake);
  Partition collect(const std::vector<int>& members);
  void set_horizons(const State& state, const std::vector<int>& awake, Partition& p);
  void reset(const std::vector<int>& members);
  double speed(const State& state, int i);
  template <class Fn>
  void near_pairs(const State& state, const std::vector<int>& awake, double time, Fn&& fn);
  const std::optional<FreePath>& path(const State& state, const Partition& p, int i);

  const Model& model_;
  const ModelIndex& index_;
  BroadPhase broad_;
  std::vector<int> parent_;       // union-find over balls
  std::vector<double> energy_;    // J, at each root: the island's energy
  std::vector<uint8_t> reached_;  // sleepers whose frozen group has joined an island ...
  std::vector<int> woken_;        // ... and the list of them
  std::vector<int> slot_;         // island number of each root while the islands are listed, else -1
  std::vector<std::optional<FreePath>> path_;  // free paths of lone balls and sleepers while the horizons are found,
  std::vector<uint8_t> path_found_;             // ... where found already,
  std::vector<int> found_;                      // ... and the sleepers among them
  bool joined_ = false;           // a join happened in this round
};

}  // namespace shotlab
