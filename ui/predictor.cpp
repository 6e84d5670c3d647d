#include "ui/predictor.hpp"

#include <algorithm>
#include <chrono>

#include "shotlab/io/scene_json.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

namespace {
constexpr double kSample = 1.0 / 120;   // s between path points
constexpr double kWallLimit = 4.0;      // s of wall time a prediction may take (a break at tight tolerances)
constexpr double kShowEvery = 8e-3;     // s of computing between hand-outs of a running prediction's paths so far
constexpr size_t kKept = 8;             // finished predictions kept (a break's is about half a megabyte)

// What a prediction depends on: the scene, every number in it, and the limit.
std::string key_of(const Scene& scene, double limit) {
  return scene_to_json(scene).dump() + "|" + std::to_string(limit);
}
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

long Predictor::request(const Scene& scene, double limit, std::vector<Scene> next) {
  const std::string key = key_of(scene, limit);
  std::function<void()> notify;
  long generation;
  {
    std::lock_guard lock(mutex_);
    generation = wanted_ = ++generation_;
    limit_ = limit;
    next_ = std::move(next);
    if (const Prediction* known = find(key)) {
      pending_.reset();
      done_ = *known;
      done_->generation = generation;
      busy_ = false;
      notify = notify_;
    } else {
      pending_ = Pending{scene, key};
      busy_ = true;
    }
  }
  wake_.notify_one();
  published_.notify_all();
  if (notify) notify();
  return generation;
}

bool Predictor::kept(const Scene& scene, double limit) const {
  const std::string key = key_of(scene, limit);
  std::lock_guard lock(mutex_);
  return find(key) != nullptr;
}

const Prediction* Predictor::find(const std::string& key) const {
  const auto it = std::find_if(kept_.begin(), kept_.end(), [&](const auto& k) { return k.first == key; });
  return it == kept_.end() ? nullptr : &it->second;
}

void Predictor::keep(std::string key, const Prediction& p) {
  std::lock_guard lock(mutex_);
  if (find(key)) return;
  kept_.emplace_back(std::move(key), p);
  if (kept_.size() > kKept) kept_.pop_front();
}

std::optional<Prediction> Predictor::latest() const {
  std::lock_guard lock(mutex_);
  return done_;
}

bool Predictor::wait_for(long generation, double seconds) const {
  std::unique_lock lock(mutex_);
  ++waiting_;
  const bool out = published_.wait_for(lock, std::chrono::duration<double>(seconds),
                                       [&] { return done_ && done_->generation == generation && done_->complete; });
  --waiting_;
  return out;
}

std::optional<double> Predictor::wall_seconds(long generation) const {
  std::lock_guard lock(mutex_);
  if (!done_ || done_->generation != generation || !done_->complete) return std::nullopt;
  return done_->wall_seconds;
}

void Predictor::publish(Prediction p) {
  std::function<void()> notify;
  {
    std::lock_guard lock(mutex_);
    if (p.generation != generation_) return;  // superseded while it ran
    if (p.complete) busy_ = false;
    done_ = std::move(p);
    notify = notify_;
  }
  published_.notify_all();
  if (notify) notify();
}

void Predictor::run() {
  for (;;) {
    Scene scene;
    std::string key;  // key_of(scene, limit), worked out once
    long generation;
    double limit;
    bool guess;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return quit_ || pending_ || !next_.empty(); });
      if (quit_) return;
      guess = !pending_;
      if (guess) {
        scene = std::move(next_.front());
        next_.erase(next_.begin());
      } else {
        scene = std::move(pending_->scene);
        key = std::move(pending_->key);
        pending_.reset();
      }
      generation = generation_;
      limit = limit_;
    }
    if (guess) {
      key = key_of(scene, limit);
      std::lock_guard lock(mutex_);
      if (find(key)) continue;
    }
    std::optional<Prediction> p = predict(scene, limit, generation, guess);
    if (!p) continue;  // superseded
    p->complete = true;
    keep(key, *p);
    if (!guess) publish(std::move(*p));
  }
}

std::optional<Prediction> Predictor::predict(const Scene& scene, double limit, long generation, bool guess) {
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
        if (sim.state().in_play[i] || out.paths[i].empty() || !out_of_play(out.paths[i].back().motion))
          out.paths[i].push_back({position(sim.state().x, i), sim.motion(i)});
    };
    sample();
    double shown = 0;  // s of computing when the paths so far were last handed out
    while (sim.time() < limit && !(sim.time() > 0 && sim.at_rest())) {
      if (wanted_ != generation) return std::nullopt;  // superseded
      if (sim.advance(kSample) != Status::Ok) {
        out.problem = sim.diagnostic().empty() ? status_name(sim.status()) : sim.diagnostic();  // it names the stop
        break;
      }
      sample();
      const auto now = std::chrono::steady_clock::now();
      const double spent = std::chrono::duration<double>(now - start).count();
      if (!guess && (waiting_ > 0 || spent - shown > kShowEvery)) {
        shown = spent;
        out.simulated = sim.time();
        out.wall_seconds = std::chrono::duration<double>(now - began).count();
        publish(out);
      }
      if (spent > kWallLimit) {
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
