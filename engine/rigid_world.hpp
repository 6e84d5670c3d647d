// The rigid model (Options::contact = Rigid; docs/model.md#rigid-model): balls that stay on the bed, move in closed
// form between events and change velocity and spin only in instants, at impulses. An event-driven loop takes the
// earliest of: a ball's change of kind (sliding to rolling, rolling to spinning or stopped), a collision of two balls,
// of a ball and a cushion or jaw, a ball's centre over a pocket's hole, a ball over the bed's edge. A separate model
// from the soft one, for speed: its accuracy against the soft one is in docs/bench/speed.md.
#pragma once
#include <string>
#include <vector>

#include "rigid_collide.hpp"
#include "runner.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

class RigidWorld final : public Runner {
 public:
  // Throws std::invalid_argument with rigid_unsupported's answer when the scene is not one for the rigid model.
  RigidWorld(Model model, State initial);

  Status advance(double dt) override;
  Status advance_on(double dt) override;
  Status advance_within(double dt, double, bool new_window) override {  // the whole dt: it is fast
    return new_window ? advance(dt) : advance_on(dt);
  }
  double time() const override { return state_.time; }
  const State& state() const override { return state_; }
  const Model& model() const override { return model_; }
  const std::vector<Event>& events() const override { return events_; }
  const Stats& stats() const override { return stats_; }
  Status status() const override { return status_; }
  const std::string& diagnostic() const override { return diagnostic_; }
  Motion motion(int ball) const override { return tracks_[ball].kind; }
  Energy energy() const override { return shotlab::energy(model_, state_); }
  Vec3 momentum() const override { return shotlab::momentum(model_, state_); }
  // None: a rigid contact lasts an instant (its impulse), and the bed's support is not a force the model computes.
  std::vector<Contact> contacts() const override { return {}; }
  bool at_rest() const override;
  // The rigid model takes no integration steps: the observer is never called.
  void set_observer(std::function<void(const StepView&)> observer) override { observer_ = std::move(observer); }
  // Each moving ball alone: nothing is integrated together.
  std::vector<std::vector<int>> island_balls() const override;

 private:
  enum class Kind { Change, Ball, Rail, Pocket, Edge };
  struct Next {
    double time;  // s
    Kind kind;
    int other;    // the ball, rail or pocket
  };
  void plan(int i);             // ball i's own next event and its pairs' next collisions, from its new track
  Next own_next(int i) const;   // the earliest of ball i's change, rails, pockets and the bed's edge
  double pair_next(int i, int j) const;
  void handle(int i, const Next& next);
  double horizontal_reach(int i, int j) const;  // m: how near two balls' centres come in the bed's plane when touching
  Bounce bounce(const ContactMaterial& material, double m_eff, double closing) const;  // closing: m/s
  void restart(int i, double t, const BallState& k);  // a new track for ball i from k at t; reports a change of kind
  void stop(Status why, std::string message);

  Model model_;
  State state_;
  std::vector<BedLaw> laws_;
  std::vector<Track> tracks_;
  std::vector<Rail> rails_;
  bool has_edge_ = false;
  Vec3 edge_origin_{0.0}, edge_u_{0.0}, edge_v_{0.0};
  std::vector<Next> own_;       // per ball
  std::vector<double> pairs_;   // s, per pair i < j at i * n + j
  std::vector<Event> events_;
  Stats stats_;
  long call_events_ = 0;
  Status status_ = Status::Ok;
  std::string diagnostic_;
  std::function<void(const StepView&)> observer_;
};

}  // namespace shotlab
