// A headless run as `shotlab run` makes it, for every program that runs scenes (the command, the Python module, the
// sweeps): the scene prepared with its cue strike, then advanced in sample slices to its duration or until rest.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "shotlab/scene.hpp"
#include "shotlab/simulation.hpp"

namespace shotlab {

inline constexpr double kStepLimitWindow = 1.0 / 60;  // s of simulated time the step limit counts over

struct HeadlessRun {
  std::unique_ptr<Simulation> sim;
  std::vector<Event> extra;  // events the engine does not make: a miscue at the strike
  bool miscue = false;       // the tip offset is beyond the cue's miscue_limit (simulated as if the tip held)
};
HeadlessRun start_run(const Scene& scene);

// Bounds on one run beyond the engine's own step limit, for programs that run many scenes nobody looked at (sweeps):
// 0 means unbounded. Checked once per kStepLimitWindow of simulated time.
struct RunLimits {
  double wall_seconds = 0;  // s of wall-clock time
  size_t max_events = 0;    // events recorded
  std::function<bool(const Simulation&)> enough;  // if set, checked after each slice: true ends the run (not a limit)
};

// The longest a run to rest goes where no duration is given: any shot's balls rest well within it (a break takes 7 s).
inline constexpr double kRestLimit = 60.0;  // s of simulated time

// How long a run goes: `duration` where given, else the scene's; with until_rest and none given, the longer of the
// scene's and kRestLimit (a scene's duration may end before its shot rests: the cut preset's 4 s, rest at 5.8 s).
double run_duration(const Scene& scene, std::optional<double> duration, bool until_rest);

// Advances to `duration` s in slices of 1 / sample_rate s, calling on_sample (if any) after each. The step limit counts
// per kStepLimitWindow of simulated time, not per slice, so that how a run is sampled never changes whether it stops.
// until_rest: stop once every ball is at rest. Without on_sample or until_rest a run whose balls all sleep jumps to
// its end (nothing changes any more). Returns the limit that ended the run early ("wall time over 60 s"), empty when
// none did (the engine's own stops are in sim.status()).
std::string advance_run(Simulation& sim, double duration, double sample_rate, bool until_rest,
                        const std::function<void()>& on_sample = {}, const RunLimits& limits = {});

// What a run to rest that ended with balls moving says ("balls still move at t = 60 s, where the run ends"); empty
// when the run was not to rest, has stopped on its own (sim.status()), or ended at rest.
std::string unfinished_rest(const Simulation& sim, bool until_rest);

}  // namespace shotlab
