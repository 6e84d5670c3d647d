#include "shotlab/io/run.hpp"

#include <algorithm>
#include <cmath>

namespace shotlab {

namespace {

bool asleep(const Simulation& sim) {
  const State& s = sim.state();
  for (int i = 0; i < s.ball_count(); ++i)
    if (s.in_play[i] && !s.sleeping(i)) return false;
  return true;
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

void advance_run(Simulation& sim, double duration, double sample_rate, bool until_rest,
                 const std::function<void()>& on_sample) {
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
    while (window_end <= sim.time()) window_end += kStepLimitWindow;
    const double to = std::min(sample, window_end);
    if (new_window) sim.advance(to - sim.time());
    else sim.advance_on(to - sim.time());
    if (to < sample) continue;
    ++k;
    if (on_sample) on_sample();
    if (until_rest && sim.at_rest()) break;
  }
}

}  // namespace shotlab
