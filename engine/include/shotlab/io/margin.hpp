// Shot margin: how much a shot forgives. The scene's cue strike replayed under a player's stroke noise (independent
// normal errors of aim, speed, tip offset and elevation), each run judged by a goal (a ball in a pocket, or a ball
// at rest inside a zone). docs/margin.md.
#pragma once
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shotlab/io/run.hpp"
#include "shotlab/scene.hpp"

namespace shotlab {

// Standard deviations of a player's stroke errors.
struct StrokeNoise {
  double aim_deg = 0;        // heading, degrees
  double speed_pct = 0;      // cue speed, % of the intended speed
  double tip_mm = 0;         // tip offset, mm, each of side and height
  double elevation_deg = 0;  // cue elevation, degrees (one-sided at a level cue: the error is folded to >= 0)
};
// The named levels (docs/margin.md gives their sources): robot, pro, amateur, beginner. Throws InputError.
StrokeNoise stroke_noise(const std::string& level);
std::vector<std::string> stroke_levels();

// What counts as success: `ball` pocketed (in `pocket`, or in any pocket when it is empty), or `ball` at rest with
// its centre within `radius` m of (x, z).
struct ShotGoal {
  enum Kind { Pocket, Zone } kind = Pocket;
  std::string ball, pocket;
  double x = 0, z = 0, radius = 0;  // m, a zone
};
// "pocket:BALL", "pocket:BALL@POCKET", "zone:BALL@X,Z,RADIUS" (m). Throws InputError naming the problem.
ShotGoal parse_goal(const std::string& text);

// The noise sources, in the order of every per-source array below.
enum NoiseSource { kAim, kSpeed, kSide, kHeight, kElevation, kNoiseSources };
const char* noise_source_name(int source);  // "aim_deg", "speed_pct", "side_mm", "height_mm", "elevation_deg"

// One replay of the shot.
struct MarginSample {
  double error[kNoiseSources] = {};  // what the stroke got wrong, in the units of noise_source_name
  bool success = false;
  std::string status = "ok";        // ok, error, limit or the engine's stop; its reason
  std::string reason;
  std::vector<double> end_x, end_z;  // each ball's end position, m (the scene's ball order)
  std::vector<bool> pocketed;  // each ball: into a pocket
  std::vector<bool> left;      // each ball: out of play, into a pocket or over a rail
};

struct MarginOptions {
  StrokeNoise noise;
  ShotGoal goal;
  size_t samples = 200;
  uint64_t seed = 1;
  int jobs = 0;               // threads, 0: one per core
  RunLimits limits{60, 100'000, {}};
  bool sensitivity = true;    // also an ensemble per noise source alone, and each parameter's tolerance interval
};

// The parameter range around the intended stroke within which the shot still succeeds, all else exact: the first
// failure found stepping out by half a noise deviation (up to 8 deviations), then bisection to 0.1 % of a step. Where
// success is not one interval (a ball that rattles in the jaws), a hole narrower than a step can be stepped over.
// lo <= 0 <= hi when the intended stroke succeeds; both 0 when it fails.
struct Tolerance {
  double lo = 0, hi = 0;
  bool bounded_lo = true, bounded_hi = true;  // false: no failure found that far out (a level cue ends elevation's)
};

struct MarginResult {
  bool nominal_success = false;          // the intended stroke, without noise
  std::vector<MarginSample> samples;     // the ensemble with every source
  double probability = 0, standard_error = 0;
  double alone[kNoiseSources] = {};      // success probability with each source alone (sensitivity)
  Tolerance tolerance[kNoiseSources];
  std::vector<std::string> ball_ids;
  bool cancelled = false;
};

// The Tolerance of one noise source (NoiseSource) alone, searched in steps of half its deviation in `options.noise`
// and bisected to `resolution` in its units (0: as shot_margin, 0.1 % of a step); both bounds 0 when the intended
// stroke fails. Throws InputError like shot_margin, or for a source out of range.
Tolerance stroke_tolerance(const Scene& scene, const MarginOptions& options, int source, double resolution = 0);

// The margin of `scene`'s cue strike (it must have one). progress(done, total) counts runs. Throws InputError when
// the scene has no cue strike or the goal names no ball of the scene.
MarginResult shot_margin(const Scene& scene, const MarginOptions& options,
                         const std::function<void(size_t, size_t)>& progress = {},
                         const std::atomic<bool>* cancel = nullptr);

// Success probability over a grid of intended aims x speeds around the scene's: cells[i_speed * aims + i_aim], each
// from `options.samples` noisy replays (sensitivity is not computed).
struct MarginMap {
  int aims = 0, speeds = 0;
  double aim_lo_deg = 0, aim_hi_deg = 0, speed_lo = 0, speed_hi = 0;  // degrees, m/s: the cells' centres span these
  std::vector<double> cells;
  bool cancelled = false;
};
MarginMap margin_map(const Scene& scene, const MarginOptions& options, int aims, int speeds, double aim_half_range_deg,
                     double speed_half_range_pct, const std::function<void(size_t, size_t)>& progress = {},
                     const std::atomic<bool>* cancel = nullptr);

// What `shotlab margin --out` writes (docs/margin.md lists the fields): the settings, the probability, the sensitivity,
// the scatter of end positions, the table's outline (for the picture) and the map when one was made.
nlohmann::json margin_to_json(const Scene& scene, const MarginOptions& options, const MarginResult& result,
                              const MarginMap* map = nullptr);
// One CSV row per replay: its stroke errors, success, status, reason and every ball's end position.
std::string margin_csv(const MarginResult& result);

}  // namespace shotlab
