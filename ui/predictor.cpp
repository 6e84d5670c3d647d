#include "ui/predictor.hpp"

#include <chrono>

#include "shotlab/simulation.hpp"

namespace shotlab {

namespace {
constexpr double kSample = 1.0 / 120;  // s between path points
constexpr double kWallLimit = 4.0;     // s of wall time a prediction may take (a break at tight tolerances)
}  // namespace

Predictor::Predictor() : thread_([this] { run(); }) {}

Predictor::~Predictor() {
  {
    std::lock_guard lock(mutex_);
    quit_ = true;
    wanted_ = -1;  // abandons the running prediction
  }
  wake_.notify_one();
  thread_.join();
}

void Predictor::set_notify(std::function<void()> notify) {
  std::lock_guard lock(mutex_);
  notify_ = std::move(notify);
}

long Predictor::request(const Scene& scene, double limit) {
  std::lock_guard lock(mutex_);
  pending_ = scene;
  limit_ = limit;
  wanted_ = ++generation_;
  busy_ = true;
  wake_.notify_one();
  return generation_;
}

std::optional<Prediction> Predictor::latest() const {
  std::lock_guard lock(mutex_);
  return done_;
}

std::optional<double> Predictor::wall_seconds(long generation) const {
  std::lock_guard lock(mutex_);
  if (!done_ || done_->generation != generation) return std::nullopt;
  return done_->wall_seconds;
}

void Predictor::run() {
  for (;;) {
    Scene scene;
    long generation;
    double limit;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_; });
      if (quit_) return;
      scene = std::move(*pending_);
      pending_.reset();
      generation = generation_;
      limit = limit_;
    }
    Prediction p = predict(scene, limit, generation);
    std::function<void()> notify;
    {
      std::lock_guard lock(mutex_);
      if (p.generation != generation_) continue;  // superseded while it ran
      done_ = std::move(p);
      busy_ = false;
      notify = notify_;
    }
    if (notify) notify();
  }
}

Prediction Predictor::predict(const Scene& scene, double limit, long generation) {
  Prediction out;
  out.generation = generation;
  const auto began = std::chrono::steady_clock::now();
  try {
    validate(scene);
    Prepared prep = prepare(scene);
    Simulation sim(std::move(prep.model), std::move(prep.state));
    out.paths.resize(sim.state().ball_count());
    const auto start = std::chrono::steady_clock::now();
    auto sample = [&] {
      for (int i = 0; i < sim.state().ball_count(); ++i)
        if (sim.state().in_play[i] || out.paths[i].empty() || out.paths[i].back().motion != Motion::Pocketed)
          out.paths[i].push_back({position(sim.state().x, i), sim.motion(i)});
    };
    sample();
    while (sim.time() < limit && !(sim.time() > 0 && sim.at_rest())) {
      if (wanted_ != generation) return out;  // superseded: the result is dropped by run()
      if (sim.advance(kSample) != Status::Ok) {
        out.problem = std::string(status_name(sim.status())) + ": " + sim.diagnostic();
        break;
      }
      sample();
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > kWallLimit) {
        out.problem = "prediction cut short after " + std::to_string(kWallLimit) + " s of computing";
        break;
      }
    }
    out.simulated = sim.time();
  } catch (const std::exception& e) {
    out.problem = e.what();
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
  return out;
}

}  // namespace shotlab
