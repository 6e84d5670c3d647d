// Splitting a scene into islands (island.hpp) that cannot touch each other for a while, so that each integrates on
// its own with its own step size (Box2D's islands, made time-aware for a soft-contact integrator).
//
// How far can a ball get? Within an island, contacts trade energy between balls, so a ball at rest can be hit and
// leave at speed. What a ball cannot do is gain more kinetic energy than its island holds: kinetic, elastic (in its
// contacts) and the height above the bed it can still fall. Ball i of an island with energy E can therefore not move
// faster than V_i = sqrt(2 E / m_i) + g h, with g h covering free fall over a horizon h. Two balls in different
// islands, a gap d apart, cannot touch before d / (V_i + V_j); a sleeping ball does not move (V = 0).
//
// Balls are grouped when they could touch within kLinkTime; the groups' energies then raise their members' bounds,
// so grouping repeats until nothing more joins. The horizon is the earliest time at which two different islands
// could touch, at most kMaxHorizon: then the simulation synchronises them and partitions again, joining islands that
// come close and splitting those that have separated. A sleeper joins the island that may reach it, with every sleeper
// frozen against it (they wake together); a sleeper that two islands may reach joins them into one.
#pragma once
#include <vector>

#include "contacts.hpp"
#include "model.hpp"
#include "state.hpp"

namespace shotlab {

struct Partition {
  std::vector<std::vector<int>> islands;  // ball indices, ascending; islands ordered by their first ball
  double horizon = 0;                     // s from the state's time: no two islands can touch before it
};

class Partitioner {
 public:
  explicit Partitioner(const Model& model) : model_(model), cache_(model) {}
  // Islands of the awake balls in play, `awake` (with the sleepers they may reach); balls out of play and sleepers
  // nothing can reach are in none.
  Partition operator()(const State& state, const std::vector<int>& awake);

 private:
  int root(int i);
  void join(int i, int j);
  void join_sleeper(int i, int sleeper, const State& state);  // with every sleeper frozen against it
  double bound(int i);  // m/s, V_i above

  const Model& model_;
  ContactCache cache_;
  std::vector<int> parent_;       // union-find over balls
  std::vector<double> energy_;    // J, at each root: the island's energy
  std::vector<uint8_t> reached_;  // sleepers whose frozen group has joined an island ...
  std::vector<int> woken_;        // ... and the list of them
  std::vector<int> slot_;         // island number of each root while the islands are listed, else -1
  bool joined_ = false;           // a join happened in this round
};

}  // namespace shotlab
