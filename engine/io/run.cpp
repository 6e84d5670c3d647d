#include "shotlab/io/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

namespace shotlab {

namespace {

bool asleep(const Simulation& sim) {
  const State& s = sim.state();
  for (int i = 0; i < s.ball_count(); ++i)
    if (s.in_play[i] && !s.sleeping(i)) return false;
  return true;
}

// The limit a run has reached, empty when none.
std::string limit_reached(const Simulation& sim, const RunLimits& limits,
                          std::chrono::steady_clock::time_point start) {
  std::ostringstream why;
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  if (limits.wall_seconds > 0 && wall.count() > limits.wall_seconds)
    why << "wall time over " << limits.wall_seconds << " s at t = " << sim.time() << " s";
  else if (limits.max_events > 0 && sim.events().size() > limits.max_events)
    why << "more than " << limits.max_events << " events by t = " << sim.time() << " s";
  return why.str();
}

}  // namespace

HeadlessRun start_run(const Scene& scene) {
  Prepared prepared = prepare(scene);
  HeadlessRun run;
  if (prepared.strike && prepared.strike->miscue) {
    run.miscue = true;
    run.extra.push_back({0.0, "miscue", {scene.cue->ball}});
  }
  run.sim = std::make_unique<Simulation>(std::move(prepared.model), std::move(prepared.state));
  return run;
}

double run_duration(const Scene& scene, std::optional<double> duration, bool until_rest) {
  if (duration) return *duration;
  return until_rest ? std::max(scene.duration, kRestLimit) : scene.duration;
}

std::string advance_run(Simulation& sim, double duration, double sample_rate, bool until_rest,
                        const std::function<void()>& on_sample, const RunLimits& limits) {
  const auto start = std::chrono::steady_clock::now();
  const double slice = 1.0 / sample_rate;
  const long slices = static_cast<long>(std::ceil(duration / slice - 1e-9));
  double window_end = 0;
  for (long k = 1; k <= slices && sim.status() == Status::Ok;) {
    if (!on_sample && !until_rest && asleep(sim)) {
      sim.advance(duration - sim.time());
      break;
    }
    const double sample = std::min(k * slice, duration);
    const bool new_window = sim.time() >= window_end;
    if (new_window)
      if (std::string why = limit_reached(sim, limits, start); !why.empty()) return why;
    while (window_end <= sim.time()) window_end += kStepLimitWindow;
    const double to = std::min(sample, window_end);
    if (new_window) sim.advance(to - sim.time());
    else sim.advance_on(to - sim.time());
    if (to < sample) continue;
    ++k;
    if (on_sample) on_sample();
    if (until_rest && sim.at_rest()) break;
    if (limits.enough && limits.enough(sim)) break;
  }
  return {};
}

std::string unfinished_rest(const Simulation& sim, bool until_rest) {
  if (!until_rest || sim.status() != Status::Ok || sim.at_rest()) return {};
  std::ostringstream why;
  why << "balls still move at t = " << sim.time() << " s, where the run ends";
  return why.str();
}

}  // namespace shotlab
