#include "world.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "check.hpp"
#include "regimes.hpp"

namespace shotlab {

World::World(Model model, State initial)
    : model_(std::move(model)),
      onset_factor_(onset_factor(model_)),
      integ_(std::move(initial)),
      index_(model_),
      partition_(model_, index_) {
  // Balls that start at rest (in their static sink on the bed, nothing moving against them, or held still off any
  // support: under a rod's anchor, in free space without gravity) sleep from the start instead of after sleep_time of
  // integrating what cannot move. The update also sizes the regime flags.
  Regimes(model_, index_).update(integ_, integ_.x, model_.options.sleep_time);
  state_ = integ_;
  const Energy e = energy();
  energy_start_ = e.total();
  energy_scale_ = e.kinetic + e.elastic + 1.0;
  energy_synced_ = energy_start_;
  std::vector<int> awake;
  for (int i = 0; i < integ_.ball_count(); ++i)
    if (integ_.active(i)) awake.push_back(i);
  regroup(integ_.time, {}, std::move(awake));
}

template <class PathA>
double World::meeting_time(double t, const std::vector<int>& balls, double energy, const PathA& path_a, Island& other,
                           double until) {
  other.state_at(t, scratch_);
  const State& flags = other.flags_at(t);
  double best = std::numeric_limits<double>::infinity();
  for (int a : balls) {
    if (!integ_.in_play[a]) continue;
    const double va = partition_.speed_bound(energy, a);
    for (size_t k = 0; k < other.balls().size(); ++k) {
      const int b = other.balls()[k];
      if (!flags.in_play[k]) continue;
      const double closing = va + partition_.speed_bound(other.energy_bound(), b);
      const double reach = model_.balls[a].radius + model_.balls[b].radius + model_.options.contact_margin;
      const double gap = glm::length(position(integ_.x, a) - position(scratch_, static_cast<int>(k))) - reach;
      if (closing > 0) best = std::min(best, std::max(gap, 0.0) / closing);
    }
  }
  // Two lone balls on free paths (regimes.hpp) may meet much later than their speed bounds say; worth a look only
  // where the speed bounds would set a deadline.
  if (t + best < until && other.balls().size() == 1 && path_a()) {
    const int a = balls[0], b = other.balls()[0];
    const auto path_b = other.free_path(t, kLoneHorizon);
    if (path_b) {
      const double reach = model_.balls[a].radius + model_.balls[b].radius + model_.options.contact_margin;
      best = std::max(best, path_meeting_time(*path_a(), *path_b, reach,
                                              partition_.speed_bound(energy, a) + partition_.speed_bound(other.energy_bound(), b)));
    }
  }
  return t + best;
}

void World::regroup(double t, std::vector<Island*> group, std::vector<int> awake) {
  integ_.time = t;
  std::vector<double> deadline;
  Partition p = split_group(t, group, awake, deadline);
  replace_group(t, group, p, deadline);
  SHOTLAB_ASSERT(islands_disjoint(), "every ball is in one island at most");
}

// The group's balls and the awake ones, split into new islands at t (the partition, and each new island's deadline).
// Every other island that could meet one of them before it got where it is joins the group, rewound to t.
Partition World::split_group(double t, std::vector<Island*>& group, std::vector<int>& awake,
                                  std::vector<double>& deadline) {
  auto in_group = [&](const Island* island) { return std::find(group.begin(), group.end(), island) != group.end(); };
  Partition p;
  for (size_t taken = 0;;) {
    // The group's balls at t (a member past t is rewound to t: its last step began at or before t).
    for (; taken < group.size(); ++taken) {
      if (!group[taken]->rewind(t)) stop(group[taken]->status(), group[taken]->diagnostic());
      group[taken]->write(t, integ_);
      for (int i : group[taken]->balls())
        if (integ_.active(i)) awake.push_back(i);
    }
    if (model_.options.islands) {
      p = partition_(integ_, awake);
    } else {  // the plain path: every ball in one system, for good
      p.islands.assign(1, std::vector<int>(integ_.ball_count()));
      std::iota(p.islands[0].begin(), p.islands[0].end(), 0);
      p.energy.assign(1, 0.0);
      p.horizon.assign(1, std::numeric_limits<double>::infinity());
    }
    // Every other island against each new one: one that could meet it before it got where it is (or very soon) must be
    // rewound to t and split with the group; the others only lower their deadlines.
    deadline.resize(p.islands.size());
    paths_.assign(p.islands.size(), std::nullopt);
    path_known_.assign(p.islands.size(), 0);
    for (size_t n = 0; n < p.islands.size(); ++n) deadline[n] = t + p.horizon[n];
    bool grew = false;
    for (const auto& other : islands_) {
      if (in_group(other.get())) continue;
      double meet = std::numeric_limits<double>::infinity();
      for (size_t n = 0; n < p.islands.size(); ++n) {
        auto path = [&, n]() -> const std::optional<FreePath>& {
          const std::vector<int>& balls = p.islands[n];
          if (!path_known_[n] && balls.size() == 1 && integ_.in_play[balls[0]])
            paths_[n] = free_path(model_, integ_, integ_.x.data(), balls[0], index_, kLoneHorizon);
          path_known_[n] = 1;
          return paths_[n];
        };
        const double m = meeting_time(t, p.islands[n], p.energy[n], path, *other, std::max(deadline[n], other->deadline()));
        deadline[n] = std::min(deadline[n], m);
        meet = std::min(meet, m);
      }
      if (meet < std::max(t + kLinkTime, other->time())) {
        group.push_back(other.get());
        grew = true;
      } else {
        other->set_deadline(std::min(other->deadline(), meet));
      }
    }
    if (!grew) return p;
  }
}

// Retires the group: events up to t are handed over (later ones are found again). A member at t that keeps exactly
// its balls goes on running (its step size and stepper history); the others end here, their energy booked at t.
void World::replace_group(double t, const std::vector<Island*>& group, Partition& p,
                               const std::vector<double>& deadline) {
  auto in_group = [&](const Island* island) { return std::find(group.begin(), group.end(), island) != group.end(); };
  std::vector<std::unique_ptr<Island>> next;
  std::vector<std::unique_ptr<Island>> ending;
  next.reserve(islands_.size() + p.islands.size());  // a regroup comes every few steps: no doubling on the way
  ending.reserve(group.size());
  for (auto& island : islands_) {
    if (!in_group(island.get())) {
      next.push_back(std::move(island));
      continue;
    }
    island->take_events(t, located_);
    ending.push_back(std::move(island));
  }
  for (size_t n = 0; n < p.islands.size(); ++n) {
    std::vector<int>& balls = p.islands[n];
    const auto same = std::find_if(ending.begin(), ending.end(), [&](const auto& island) {
      return island && island->time() == t && island->balls() == balls;
    });
    if (same != ending.end()) {
      next.push_back(std::move(*same));
    } else {
      // A new island starts with the smallest next step of the islands its balls come from.
      double first = std::numeric_limits<double>::infinity();
      for (const auto& island : ending)
        if (island)
          for (int i : island->balls())
            if (std::binary_search(balls.begin(), balls.end(), i)) first = std::min(first, island->next_step());
      if (!std::isfinite(first)) first = model_.integrator.initial_step;
      next.push_back(std::make_unique<Island>(model_, index_, integ_, std::move(balls), first, p.energy[n], onset_factor_));
      // While it holds them, its balls are no sleepers to the partitioner (their flags here are as they joined).
      for (int i : next.back()->balls()) integ_.asleep[i] = 0;
    }
    next.back()->set_deadline(deadline[n]);
  }
  for (const auto& island : ending) {
    if (!island) continue;
    energy_synced_ += island->energy() - island->energy_ref();  // it is at t (rewound)
    retired_ += island->stats();
    // Its balls at the clock: those in no new island stay as they are now (the others are interpolated anew).
    for (int i : island->balls()) copy_ball(integ_, i, state_, i);
  }
  islands_ = std::move(next);
}

bool World::islands_disjoint() const {
  std::vector<uint8_t> seen(integ_.ball_count(), 0);
  for (const auto& island : islands_)
    for (int i : island->balls())
      if (seen[i]++) return false;
  return true;
}

std::vector<std::vector<int>> World::island_balls() const {
  std::vector<std::vector<int>> out;
  for (const auto& island : islands_) out.push_back(island->balls());
  return out;
}

bool World::at_rest() const {
  for (const auto& island : islands_)  // balls in no island sleep or are out of play
    for (int i : island->balls()) {
      if (state_.sleeping(i)) continue;  // frozen at rest
      const Motion m = motion(i);
      if (m != Motion::Stationary && !out_of_play(m)) return false;
    }
  return true;
}

Status World::advance(double dt) {
  for (const auto& island : islands_) island->start_call();
  return run(dt, std::numeric_limits<double>::infinity());
}

Status World::advance_on(double dt) { return run(dt, std::numeric_limits<double>::infinity()); }

Status World::advance_within(double dt, double wall_seconds, bool new_window) {
  if (new_window)
    for (const auto& island : islands_) island->start_call();
  return run(dt, wall_seconds);
}

Status World::run(double dt, double wall_seconds) {  // dt checked by Simulation
  if (status_ != Status::Ok) return status_;
  const auto wall0 = std::chrono::steady_clock::now();
  const double target = state_.time + dt;
  const bool budgeted = wall_seconds < std::numeric_limits<double>::infinity();
  // Always step the island that is furthest behind: then every island's last step spans the time of any stop, and
  // the caller's clock can be read off every island's dense output.
  double reached = target;
  bool stepped = false;
  while (status_ == Status::Ok && !islands_.empty()) {
    const auto next = std::min_element(islands_.begin(), islands_.end(),
                                       [](const auto& a, const auto& b) { return a->time() < b->time(); });
    Island& island = **next;
    if (island.time() >= target) break;
    if (budgeted && stepped &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count() >= wall_seconds) {
      reached = std::max(state_.time, island.time());  // the furthest behind: every island's last step spans it
      break;
    }
    if (island.time() >= island.deadline()) {
      const double at = island.time();
      regroup(at, {&island}, {});  // which may end the island
      if (status_ != Status::Ok) reached = at;  // a member could not be rewound: stay where the regroup was
      continue;
    }
    if (island.call_steps() >= model_.integrator.max_steps_per_call) {
      std::ostringstream msg;
      msg << "step limit: " << model_.integrator.max_steps_per_call << " steps (integrator.max_steps_per_call) did not reach t = "
          << target << " s; stopped at t = " << island.time() << " s with step " << island.stats().last_step << " s. "
          << island.describe_balls();
      stop(Status::StepLimit, msg.str());
    } else {
      stepped = true;
      if (!island.step(island.deadline())) stop(island.status(), island.diagnostic());
      else if (observer_) observer_(island.view());
    }
    if (status_ != Status::Ok) reached = island.time();  // stay at the last good point
  }
  // The state at the clock; balls in no island stay as their last island left them. Events are handed over up
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
  if (status_ == Status::Ok) check_energy();
  stats_.wall_seconds = wall + std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return status_;
}

void World::check_energy() {
  // Each island's energy at the end of its last step: islands run on their own clocks, and each is worked out once a
  // step (a lone ball rolls for several frames in one).
  double e = energy_synced_;
  for (const auto& island : islands_) e += island->energy() - island->energy_ref();
  if (e - energy_start_ > energy_scale_) {
    std::ostringstream msg;
    msg << "unstable: the total energy grew from " << energy_start_ << " J to " << e << " J by t = " << state_.time
        << " s, which a passive system cannot do: "
        << (is_adaptive(model_.integrator.method)
                ? "the tolerances let the steps grow too large for the contact stiffness (tighten abs_tol and rel_tol, "
                  "or use a softer material). "
                : "the step is too large for the contact stiffness (use an adaptive method, a smaller fixed step or a "
                  "softer material). ");
    for (const auto& island : islands_) msg << island->describe_balls() << " ";
    stop(Status::Unstable, msg.str());
  }
}

void World::stop(Status why, std::string message) {
  status_ = why;
  diagnostic_ = std::move(message);
}

}  // namespace shotlab
