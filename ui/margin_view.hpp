// The shot lab's margin (players and coaches): how much the shot being aimed forgives, worked out in the background
// whenever the aim or the table changes (shotlab/io/margin.hpp), and a map of success over aim x speed. The panel
// (panel_margin.cpp) edits the choices here; the overlay draws the end positions of the replays.
#pragma once
#include <string>
#include <vector>

#include "shotlab/io/margin.hpp"
#include "ui/background.hpp"

namespace shotlab {

class Lab;

struct MarginEstimate {
  std::string key;  // what it was worked out for (margin_key)
  MarginOptions options;
  MarginResult result;
};
struct MarginMapResult {
  std::string key;  // margin_map_key: the table without the aim and speed
  MarginMap map;
};

inline constexpr int kMapSizes[][2] = {{20, 10}, {40, 20}};  // aims x speeds

struct MarginView {
  bool open = false;        // the panel's section is open: only then is anything worked out
  int pocket = 0;           // 0: the aimed-at ball into any pocket, k: into the table's pocket k - 1
  bool target_goal = false; // the cue ball stops inside the practice target instead
  int level = 2;            // index in stroke_levels(): amateur
  int samples = 200;        // replays of the estimate
  bool scatter = true;      // draw where the replays left the balls
  int map_size = 0;         // index in kMapSizes
  int map_samples = 50;     // replays per cell
  double map_speed = 15;    // the map's half range of speed, % of the speed
  // The map's half range of aim, degrees: four of the player's aim deviations (amateur 2, pro 1), past which the
  // success of a shot whose own window is a fraction of a degree has fallen to nothing.
  double map_aim() const { return 4 * stroke_noise(stroke_levels()[static_cast<size_t>(level)]).aim_deg; }
  bool map_wanted = false;  // asked for and not cancelled: kept up to date
  bool map_current = false; // the map's result is for the table and goal as they are, and covers the aim and speed
  Background<MarginEstimate> estimate;
  Background<MarginMapResult> map;
  std::string asked, map_asked;  // keys of the last requests
  std::string problem;           // why nothing can be worked out (no cue strike, no ball aimed at)

  bool busy() const { return estimate.busy() || map.busy(); }
};

// The options for the lab's scene as the view's choices make them; nullopt (and `why`) when there is no goal.
std::optional<MarginOptions> margin_options(const Lab& lab, const MarginView& view, std::string& why);
std::string margin_key(const Lab& lab, const MarginOptions& options);
std::string margin_map_key(const Lab& lab, const MarginView& view, const MarginOptions& options);

// Once a frame: starts the estimate (and the map, if wanted) when what it depends on changed; cancels both while the
// section is closed or a shot is shown.
void update_margin(const Lab& lab, MarginView& view);

// The latest estimate if it is for the scene as it is now.
std::optional<MarginEstimate> fresh_estimate(const Lab& lab, const MarginView& view);

}  // namespace shotlab
