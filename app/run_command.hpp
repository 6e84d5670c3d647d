// `shotlab run`: a scene file simulated headless, with its result, events and trajectory written out.
#pragma once
#include <optional>
#include <string>
#include <vector>

namespace shotlab {

inline constexpr double kMinSampleRate = 1e-3, kMaxSampleRate = 1e5;  // Hz

struct RunOptions {
  std::string scene;
  std::optional<double> duration;      // s, overrides the scene's
  std::vector<std::string> overrides;  // PATH=VALUE
  std::string out;                     // RESULT.json, empty: none
  std::string trajectory;              // CSV, empty: none
  double sample_rate = 60;             // Hz, trajectory samples (also the advance() slice)
  double max_samples = 1e6;            // runs of more samples (duration x sample rate) are refused
  bool until_rest = false;             // stop once every ball is at rest (run_duration: up to kRestLimit)
  bool quiet = false;
};

// Exit status: 0 success, 1 bad input or a file that cannot be written (message on stderr), 3 the simulation stopped
// (step limit, non-finite state, unstable).
int run_scene(const RunOptions& options);

}  // namespace shotlab
