#include "ui/shot.hpp"

#include <algorithm>
#include <chrono>

namespace shotlab {

namespace {
constexpr double kFrameStep = 1.0 / 240;  // s of simulated time between recorded frames at normal speed
constexpr double kMinFrameGap = 2e-5;      // s: in deep slow motion, frames closer than this are not recorded
constexpr size_t kMaxSamples = 20000;      // step-size samples kept (a break takes ~10k steps)
}  // namespace

Shot::Shot(const Scene& start) : start_(start), chunk_(kFrameStep) {
  validate(start_);
  Prepared p = prepare(start_);
  sim_ = std::make_unique<Simulation>(std::move(p.model), std::move(p.state));
  sim_->set_observer([this](const Island& island) { observe(island); });
  record();
}

void Shot::observe(const Island& island) {
  const StepSpan& span = island.span();
  if (step_sizes_.size() < kMaxSamples) step_sizes_.push_back({span.t1, span.t1 - span.t0});
  // Largest ball-ball normal force at the end of the step; a gap of 5 ms without one starts a new collision.
  // Most steps have no touching pair: a distance check keeps the full contact evaluation off them.
  const auto& in_play = island.state().in_play;
  const auto& balls = island.model().balls;
  bool touching = false;
  for (size_t i = 0; i < balls.size() && !touching; ++i)
    for (size_t j = i + 1; j < balls.size() && !touching; ++j)
      touching = in_play[i] && in_play[j] &&
                 glm::length(position(span.x1, i) - position(span.x1, j)) < balls[i].radius + balls[j].radius;
  if (!touching) return;
  const State probe{span.t1, span.x1, in_play, {}, {}, {}, {}};
  double force = 0;
  for (const Contact& c : contacts(island.model(), probe))
    if (c.other_ball >= 0) force = std::max(force, c.force.normal);
  if (force <= 0) return;
  if (span.t1 - last_contact_time_ > 5e-3) collision_force_.clear();
  last_contact_time_ = span.t1;
  if (collision_force_.size() < kMaxSamples) collision_force_.push_back({span.t1, force});
}

void Shot::record() {
  const State& s = sim_->state();
  Frame f{s.time, s, {}, {}, 0};
  const int n = s.ball_count();
  if (frames_.empty()) {
    f.orientation.assign(n, glm::dquat(1, 0, 0, 0));
  } else {
    // Turn by the mean angular velocity over the frame (exact for the linear spin decay on the cloth).
    const Frame& prev = frames_.back();
    const double dt = s.time - prev.time;
    f.orientation = prev.orientation;
    for (int i = 0; i < n; ++i) {
      const Vec3 w = 0.5 * (spin(s.x, i) + spin(prev.state.x, i));
      const double angle = glm::length(w) * dt;
      if (angle > 0) f.orientation[i] = glm::normalize(glm::angleAxis(angle, glm::normalize(w)) * prev.orientation[i]);
    }
  }
  for (int i = 0; i < n; ++i) f.motion.push_back(sim_->motion(i));
  f.energy = sim_->energy().total();
  frames_.push_back(std::move(f));
}

double Shot::advance(double target, double budget) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  const Stats before = sim_->stats();
  while (sim_->time() < target && !finished()) {
    // One advance() cannot be interrupted, so when the integrator crawls (thousands of tiny steps in a pile-up)
    // the chunks shrink to keep each frame within its budget; they grow back once steps are cheap again.
    const auto before_chunk = clock::now();
    const double to = std::min(target, sim_->time() + chunk_);
    sim_->advance(to - sim_->time());
    const double took = std::chrono::duration<double>(clock::now() - before_chunk).count();
    if (took > budget / 2) chunk_ = std::max(chunk_ / 4, 1e-7);
    else if (took < budget / 8) chunk_ = std::min(chunk_ * 2, kFrameStep);
    if (sim_->time() - frames_.back().time >= kMinFrameGap || finished()) record();
    if (std::chrono::duration<double>(clock::now() - start).count() > budget) break;
  }
  last_steps_ = sim_->stats().steps - before.steps;
  last_rhs_ = sim_->stats().rhs_evaluations - before.rhs_evaluations;
  return sim_->time();
}

bool Shot::finished() const {
  return sim_->status() != Status::Ok || sim_->time() >= start_.duration || (sim_->time() > 0 && sim_->at_rest());
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

}  // namespace shotlab
