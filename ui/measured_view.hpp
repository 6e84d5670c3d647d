// A measured shot in the shot lab (developers tuning contacts): its tracked balls drawn over the table beside the
// simulated paths, and the fit of its cue strike (and, if chosen, shared materials) run in the background
// (shotlab/io/fit.hpp). The Tuning tab's section (panel_measured.cpp) edits this; the overlay draws the tracks.
#pragma once
#include <optional>
#include <string>

#include "shotlab/io/fit.hpp"
#include "ui/background.hpp"

namespace shotlab {

// The values the lab offers to fit beside the strike (paths as --set names them) and their labels.
inline constexpr const char* kLabFitPaths[][2] = {
    {"materials.ball_cloth.friction", "cloth friction"},
    {"materials.ball_cloth.rolling_resistance", "rolling resistance"},
    {"materials.ball_cloth.spin_friction", "spin friction"},
    {"materials.ball_cushion.friction", "cushion friction"},
    {"materials.ball_cushion.damping", "cushion damping"},
    {"materials.ball_ball.friction", "ball-ball friction"}};
inline constexpr int kLabFitValues = 6;

struct MeasuredView {
  std::optional<MeasuredShot> shot;  // the measured shot the scene was made from
  std::string path;
  bool fit_value[kLabFitValues] = {};
  Background<FitResult> fit;
  size_t applied = 0;                // fits whose result has been put into the scene
  std::optional<FitResult> last;     // the last fit applied (its errors are shown)
};

}  // namespace shotlab
