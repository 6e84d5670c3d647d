// Calibration: the cue strike of each measured shot, and scene values shared by all of them (materials), fitted so
// that the simulated balls pass where the tracked ones were, by least squares on the positions at the measured times
// (Ceres Solver, Levenberg-Marquardt with central numeric derivatives). docs/fit.md.
#pragma once
#include <atomic>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "shotlab/io/measured.hpp"
#include "shotlab/scene.hpp"

namespace shotlab {

// A shot's cue strike as the fit sees it: what the player did and when.
struct CueFit {
  double speed = 0;          // cue speed, m/s
  double aim_deg = 0;        // heading, degrees (0 = +x, 90 = -z)
  double side = 0, height = 0;  // tip offsets, ball radii
  double elevation_deg = 0;  // degrees
  double strike_time = 0;    // s on the measured clock
};

struct FitSettings {
  std::vector<std::string> paths;  // scene values fitted in common (--fit), e.g. materials.ball_cloth.friction
  bool elevation = false;          // fit each cue's elevation too (else a level cue)
  int threads = 0;                 // 0: one per core
  int max_iterations = 100;        // of the joint fit
  std::function<void(const std::string&)> log;  // a line per stage
  std::function<void(size_t, size_t)> progress;   // windows fitted of the round's windows (every round starts at 0)
  const std::atomic<bool>* cancel = nullptr;       // set: the fit stops soon and returns what it has
};

struct ShotFit {
  std::string name, cue_ball;
  CueFit start, cue;                 // the data's starting guess and the fitted strike
  CueFit sd;                         // standard deviations where the fit gives them (NaN where not)
  std::map<std::string, double> rms;  // m: root mean square distance, simulated to measured centre, per ball
  std::map<std::string, std::vector<MeasuredSample>> simulated;  // at the measured times
};

struct FitResult {
  std::vector<std::string> paths;
  std::vector<double> start, values, sd;  // per path: the scene's value, the fitted one, its standard deviation
  std::vector<ShotFit> shots;
  double seconds = 0;
  int iterations = 0;
  std::string report;                     // the optimiser's one-line summary
};

// The starting guess from the data: direction and ball speed from the cue ball's first moved samples, the strike
// time extrapolated back to its start, the cue speed that gives that ball speed with a centre hit.
CueFit initial_cue(const Scene& base, const MeasuredShot& shot);

// The scene of a measured shot: the base scene's table, materials and cue, the balls where they were first seen (ball
// specs from the base scene's balls of the same id, else its first ball's), the given strike.
Scene measured_scene(const Scene& base, const MeasuredShot& shot, const CueFit& cue);

// Fits every shot's cue strike, then those and the shared values together. Throws InputError for a path that names
// no number in the scene.
FitResult fit_measured(const Scene& base, const std::vector<MeasuredShot>& shots, const FitSettings& settings);

// The base scene with the fitted values set.
Scene fitted_scene(const Scene& base, const FitResult& fit);

// What `shotlab fit --out` writes (docs/fit.md lists the fields).
nlohmann::json fit_to_json(const Scene& base, const std::vector<MeasuredShot>& shots, const FitResult& fit);

}  // namespace shotlab
