// What runs a Simulation (simulation.hpp): advance(dt) moves the clock to exactly t + dt. The scene is split into islands (island.hpp), each
// integrated on its own clock with its own steps up to its own deadline, before which nothing outside it can touch it
// (partition.hpp). An island that reaches its deadline is looked at again, alone or with the islands it may now
// reach: they are joined and split anew, and the others run on. Every island steps on its own schedule, independent
// of how the caller slices time: it steps past the target and the state at the target comes from the step's dense
// output. Frames of 1/30 s, 1/240 s or one call give bit-identical results.
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "shotlab/diagnostics.hpp"
#include "island.hpp"
#include "shotlab/model.hpp"
#include "partition.hpp"
#include "runner.hpp"
#include "shotlab/state.hpp"

namespace shotlab {

class World final : public Runner {
 public:
  World(Model model, State initial);
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  // Advance the clock by dt >= 0 s (a negative dt throws std::invalid_argument). Returns Ok, or why it stopped (then status() stays so and diagnostic() says
  // where and which balls; further calls do nothing).
  Status advance(double dt) override;
  // As advance(), but the step limit (max_steps_per_call) keeps counting from the previous call: a caller that stops
  // at sample times inside a window of its own counts the limit per window, however it samples.
  Status advance_on(double dt) override;
  // As advance(), but stopping once `wall_seconds` have passed (Simulation::advance_within).
  Status advance_within(double dt, double wall_seconds, bool new_window) override;

  double time() const override { return state_.time; }
  const State& state() const override { return state_; }
  const Model& model() const override { return model_; }
  const std::vector<Event>& events() const override { return events_; }
  const Stats& stats() const override { return stats_; }
  Status status() const override { return status_; }
  const std::string& diagnostic() const override { return diagnostic_; }

  Motion motion(int ball) const override { return classify(model_, index_, state_, state_.x.data(), ball); }
  Energy energy() const override { return shotlab::energy(model_, state_); }
  Vec3 momentum() const override { return shotlab::momentum(model_, state_); }
  std::vector<Contact> contacts() const override { return shotlab::contacts(model_, state_); }
  // True when every ball in play is stationary (or out of play): nothing will move again.
  bool at_rest() const override;

  // Called after every accepted step of any island (odeint's observer): step-size plots, per-contact counts.
  void set_observer(std::function<void(const StepView&)> observer) override { observer_ = std::move(observer); }
  // The balls (scene indices) each island integrates together now.
  std::vector<std::vector<int>> island_balls() const override;

 private:
  // Splits the balls of `group` (islands at time t or, one step at most, past it) and the awake balls `awake` (in no
  // island) into new islands at time t, taking in every other island that could meet them before it got where it is.
  void regroup(double t, std::vector<Island*> group, std::vector<int> awake);
  Partition split_group(double t, std::vector<Island*>& group, std::vector<int>& awake, std::vector<double>& deadline);
  void replace_group(double t, const std::vector<Island*>& group, Partition& p, const std::vector<double>& deadline);
  bool islands_disjoint() const;
  // s: the earliest time at which `balls` (at time t in integ_, in an island of energy `energy`; path_a: their free
  // path where they are a lone ball on one, else nullopt) could touch a ball of `other` (at time t on its dense output); a closer
  // look only for a bound before `until` (s).
  // path_a() is asked for only where it can matter (it may cost a look at the colliders).
  template <class PathA>
  double meeting_time(double t, const std::vector<int>& balls, double energy, const PathA& path_a, Island& other,
                      double until);
  // advance()'s loop: every island to state_.time + dt, or to where it stops after wall_seconds (advance_within).
  Status run(double dt, double wall_seconds);
  void check_energy();
  void stop(Status why, std::string message);

  Model model_;
  double onset_factor_;  // of the stepper (stepper.hpp), for every island
  State integ_;  // balls in no island as they are; the others as their island last left or joined them
  State state_;  // the state at the caller's clock, interpolated
  ModelIndex index_;  // of model_: the scene's material names resolved, once
  Partitioner partition_;
  std::vector<std::unique_ptr<Island>> islands_;
  StateVector scratch_;
  std::vector<Event> events_;
  Stats stats_, retired_;  // retired_: what islands no longer running did
  Status status_ = Status::Ok;
  std::string diagnostic_;
  std::function<void(const StepView&)> observer_;
  double energy_start_, energy_scale_;  // J: total at t = 0, and what it may grow by before the run is Unstable
  // J: the total as of the islands' energy references (each island's start). Balls in no island do not move, so the
  // total at any later time is this plus what the islands' energies changed since: the check after every advance()
  // costs O(balls in islands).
  double energy_synced_;
  std::vector<Event> located_;  // taken from islands, not yet handed over
  // split_group's cache: paths_[n], the free path of new island n's lone ball, worked out the first time a meeting
  // time asks for it (path_known_[n]).
  std::vector<std::optional<FreePath>> paths_;
  std::vector<uint8_t> path_known_;
};

}  // namespace shotlab
