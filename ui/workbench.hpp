// What the shot lab holds about the scene on the table beside the scene itself: the shots kept to compare, the A of
// the A/B overlay, the target, and the measured shot the scene was made from. A file load starts them afresh; undoing
// the load brings them back with the scene (history.hpp).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "shotlab/io/fit.hpp"
#include "shotlab/io/measured.hpp"
#include "ui/predictor.hpp"
#include "ui/shot.hpp"

namespace shotlab {

using Trails = std::vector<std::vector<PathPoint>>;  // per ball

// A shot kept to compare with later ones: its trails and the cue settings that made it.
struct KeptShot {
  std::string label;
  Trails trails;
  int colour = 0;
  bool visible = true;
};

struct Workbench {
  std::vector<KeptShot> kept;
  Trails compare;                        // the A of the A/B overlay
  std::string compare_label;
  std::optional<Vec3> target;            // where the cue ball should stop
  std::optional<MeasuredShot> measured;  // the measured shot the scene was made from, its CSV file
  std::string measured_path;
  std::optional<FitResult> measured_fit;  // the last fit of it applied
  std::vector<Frame> compare_frames;     // A's frames: its lines in the plots
};

}  // namespace shotlab
