#include "ui/shot.hpp"

#include <algorithm>
#include <chrono>

namespace shotlab {

namespace {
constexpr double kFrameStep = 1.0 / 240;  // s of simulated time between recorded frames at normal speed
constexpr double kMinFrameGap = 2e-5;      // s: in deep slow motion, frames closer than this are not recorded
constexpr size_t kMaxSamples = 20000;      // step-size samples kept (a break takes ~5k steps)

std::unique_ptr<Simulation> simulation_of(const Scene& scene) {
  Prepared p = prepare(scene);
  return std::make_unique<Simulation>(std::move(p.model), std::move(p.state));
}

// Turns each ball by its mean angular velocity over dt (exact for the linear spin decay on the cloth).
void turn(std::vector<glm::dquat>& q, const State& from, const State& to, double dt) {
  for (int i = 0; i < to.ball_count(); ++i) {
    const Vec3 w = 0.5 * (spin(to.x, i) + spin(from.x, i));
    const double angle = glm::length(w) * dt;
    if (angle > 0) q[i] = glm::normalize(glm::angleAxis(angle, glm::normalize(w)) * q[i]);
  }
}
}  // namespace

Shot::Shot(const Scene& start, double safety_limit) : start_(start), limit_(safety_limit) {
  validate(start_);
  sim_ = simulation_of(start_);
  sim_->set_observer([this](const StepView& step) {
    if (step_sizes_.size() < kMaxSamples) step_sizes_.push_back({step.t1, step.t1 - step.t0});
  });
  record();
}

Frame Shot::frame_from(const Simulation& sim, double t) const {
  const State& s = sim.state();
  Frame f{t, s, {}, {}, sim.energy()};
  for (int i = 0; i < s.ball_count(); ++i) f.motion.push_back(sim.motion(i));
  return f;
}

void Shot::record() {
  Frame f = frame_from(*sim_, sim_->time());
  if (frames_.empty()) {
    f.orientation.assign(f.state.ball_count(), glm::dquat(1, 0, 0, 0));
  } else {
    f.orientation = frames_.back().orientation;
    turn(f.orientation, frames_.back().state, f.state, f.time - frames_.back().time);
  }
  frames_.push_back(std::move(f));
}

double Shot::advance(double target, double budget) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  auto spent = [&] { return std::chrono::duration<double>(clock::now() - start).count(); };
  const Stats before = sim_->stats();
  target = std::min(target, limit_);
  // Frames of kFrameStep are recorded for replay. The engine itself stops once the budget is spent (a step past it
  // at most), so a frame that meets thousands of small steps (a rack's first millisecond) keeps to its budget.
  // A window of kFrameStep is one count of the step limit however many frames it takes.
  while (sim_->time() < target && !finished()) {
    const bool new_window = !(sim_->time() < window_end_);
    if (new_window) window_end_ = sim_->time() + kFrameStep;
    const double to = std::min(target, window_end_);
    sim_->advance_within(to - sim_->time(), std::max(budget - spent(), 0.0), new_window);
    if (sim_->time() - frames_.back().time >= kMinFrameGap || finished()) record();
    if (sim_->time() < to || spent() > budget) break;
  }
  last_steps_ = sim_->stats().steps - before.steps;
  last_rhs_ = sim_->stats().rhs_evaluations - before.rhs_evaluations;
  last_wall_ = spent();
  return sim_->time();
}

ShotEnd Shot::end() const {
  if (sim_->status() != Status::Ok) return ShotEnd::EngineStop;
  if (sim_->time() > 0 && sim_->at_rest()) return ShotEnd::Rest;
  if (sim_->time() >= limit_) return ShotEnd::SafetyLimit;
  return ShotEnd::Running;
}

double Shot::realtime_factor() const {
  const double wall = sim_->stats().wall_seconds;
  return wall > 0 ? sim_->time() / wall : 0.0;
}

Frame Shot::frame_at(double t) const {
  auto it = std::upper_bound(frames_.begin(), frames_.end(), t, [](double v, const Frame& f) { return v < f.time; });
  if (it == frames_.begin()) return frames_.front();
  if (it == frames_.end()) return frames_.back();
  const Frame& a = *(it - 1);
  const Frame& b = *it;
  Frame out = a;
  const double s = (t - a.time) / (b.time - a.time);
  out.time = t;
  for (int i = 0; i < a.state.ball_count(); ++i) {
    set_position(out.state.x, i, glm::mix(position(a.state.x, i), position(b.state.x, i), s));
    out.orientation[i] = glm::slerp(a.orientation[i], b.orientation[i], s);
  }
  return out;
}

Frame Shot::exact_frame(double t) {
  t = std::clamp(t, 0.0, sim_->time());
  if (!scrub_ || scrub_->time() > t) scrub_ = simulation_of(start_);  // the clock only runs forward: start again
  if (t > scrub_->time()) scrub_->advance(t - scrub_->time());
  Frame f = frame_from(*scrub_, t);
  f.orientation = frame_at(t).orientation;
  return f;
}

}  // namespace shotlab
