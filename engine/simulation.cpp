#include "simulation.hpp"

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "regimes.hpp"

namespace shotlab {

Simulation::Simulation(Model model, State initial)
    : model_(std::move(model)),
      integ_(std::move(initial)),
      cache_(model_),
      partition_(model_),
      sync_time_(integ_.time) {
  // Balls that start at rest (in their static sink on the bed, nothing moving against them) sleep from the start
  // instead of after sleep_time of integrating a contact that cannot move. The update also sizes the regime flags.
  Regimes(model_).update(integ_, integ_.x, model_.options.sleep_time);
  state_ = integ_;
  const Energy e = energy();
  energy_start_ = e.total();
  energy_scale_ = e.kinetic + e.elastic + 1.0;
  energy_synced_ = energy_start_;
  synchronise();
}

void Simulation::synchronise() {
  for (const auto& island : islands_) {
    island->write(sync_time_, integ_);
    island->take_events(sync_time_, located_);
    const double e = island->energy(sync_time_);
    energy_synced_ += e - island->energy_ref();
    island->set_energy_ref(e);
  }
  integ_.time = sync_time_;
  Partition p;
  if (model_.options.islands) {
    // Awake balls are in islands (all of them, at the start).
    std::vector<int> awake;
    if (islands_.empty()) {
      for (int i = 0; i < integ_.ball_count(); ++i)
        if (integ_.active(i)) awake.push_back(i);
    }
    for (const auto& island : islands_)
      for (int i : island->balls())
        if (integ_.active(i)) awake.push_back(i);
    p = partition_(integ_, awake);
  } else {  // the plain path: every ball in one system, for good
    p.islands.emplace_back(integ_.ball_count());
    std::iota(p.islands[0].begin(), p.islands[0].end(), 0);
    p.horizon = std::numeric_limits<double>::infinity();
  }
  // An island that keeps its balls keeps running (its step size and stepper history); a new one starts with the
  // smallest next step of the islands its balls come from.
  std::vector<double> step_of(integ_.ball_count(), model_.integrator.initial_step);
  for (const auto& island : islands_)
    for (int i : island->balls()) step_of[i] = island->next_step();
  std::vector<std::unique_ptr<Island>> next;
  for (std::vector<int>& balls : p.islands) {
    const auto same = std::find_if(islands_.begin(), islands_.end(),
                                   [&](const auto& island) { return island && island->balls() == balls; });
    if (same != islands_.end()) {
      next.push_back(std::move(*same));
      continue;
    }
    double first = std::numeric_limits<double>::infinity();
    for (int i : balls) first = std::min(first, step_of[i]);
    next.push_back(std::make_unique<Island>(model_, integ_, std::move(balls), first));
  }
  for (const auto& island : islands_) {
    if (!island) continue;
    retired_ += island->stats();
    // Its balls at the clock: those in no new island stay as they are now (the others are interpolated anew).
    for (int i : island->balls()) copy_ball(integ_, i, state_, i);
  }
  islands_ = std::move(next);
  sync_time_ = integ_.time + p.horizon;
}

bool Simulation::at_rest() const {
  for (const auto& island : islands_)  // balls in no island sleep or are out of play
    for (int i : island->balls()) {
      if (state_.sleeping(i)) continue;  // frozen at rest
      const Motion m = motion(i);
      if (m != Motion::Stationary && m != Motion::Pocketed) return false;
    }
  return true;
}

Status Simulation::advance(double dt) {
  // The clock only runs forward: the dense output of the last step cannot go back past its start.
  if (!(dt >= 0)) throw std::invalid_argument("Simulation::advance: dt must be >= 0 s, got " + std::to_string(dt));
  if (status_ != Status::Ok) return status_;
  const auto wall0 = std::chrono::steady_clock::now();
  const double target = state_.time + dt;
  std::vector<int> steps(islands_.size(), 0);
  // Always step the island that is furthest behind: then every island's last step spans the time of any stop, and
  // the caller's clock can be read off every island's dense output.
  double reached = target;
  while (status_ == Status::Ok && !islands_.empty()) {
    const auto next = std::min_element(islands_.begin(), islands_.end(),
                                       [](const auto& a, const auto& b) { return a->time() < b->time(); });
    Island& island = **next;
    if (island.time() >= target) break;
    if (island.time() >= sync_time_) {
      synchronise();
      steps.assign(islands_.size(), 0);
      continue;
    }
    if (steps[next - islands_.begin()]++ >= model_.integrator.max_steps_per_call) {
      std::ostringstream msg;
      msg << "step limit: " << model_.integrator.max_steps_per_call << " steps in one advance() did not reach t = "
          << target << " s; stopped at t = " << island.time() << " s with step " << island.stats().last_step << " s. "
          << island.describe_balls();
      stop(Status::StepLimit, msg.str());
    } else if (!island.step(sync_time_)) {
      stop(island.status(), island.diagnostic());
    } else if (observer_) {
      observer_(island);
    }
    if (status_ != Status::Ok) reached = island.time();  // stay at the last good point
  }
  // The state at the clock; balls in no island stay as the last synchronisation left them. Events are handed over up
  // to the time every island has reached (a little past the clock): no island can locate an earlier one later.
  double frontier = std::numeric_limits<double>::infinity();
  for (const auto& island : islands_) frontier = std::min(frontier, island->time());
  const double wall = stats_.wall_seconds;
  stats_ = retired_;
  for (const auto& island : islands_) {
    island->write(std::min(reached, island->time()), state_);
    island->take_events(frontier, located_);
    stats_ += island->stats();
    stats_.last_step = island->stats().last_step;
  }
  state_.time = reached;
  std::stable_sort(located_.begin(), located_.end(), [](const Event& a, const Event& b) {
    return a.time < b.time || (a.time == b.time && a.bodies < b.bodies);
  });
  events_.insert(events_.end(), located_.begin(), located_.end());
  located_.clear();
  if (status_ == Status::Ok) check_energy(reached);
  stats_.wall_seconds = wall + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return status_;
}

void Simulation::check_energy(double t) {
  double e = energy_synced_;
  for (const auto& island : islands_) e += island->energy(t) - island->energy_ref();
  if (e - energy_start_ > energy_scale_) {
    std::ostringstream msg;
    msg << "unstable: the total energy grew from " << energy_start_ << " J to " << e << " J by t = " << state_.time
        << " s, which a passive system cannot do: the step is too large for the contact stiffness (use an adaptive "
           "method, a smaller fixed step or a softer material). ";
    for (const auto& island : islands_) msg << island->describe_balls() << " ";
    stop(Status::Unstable, msg.str());
  }
}

void Simulation::stop(Status why, std::string message) {
  status_ = why;
  diagnostic_ = std::move(message);
}

}  // namespace shotlab
