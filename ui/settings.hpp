// What persists between runs: $XDG_CONFIG_HOME/shotlab/settings.json (or ~/.config/shotlab). ImGui keeps its
// window state in imgui.ini beside it. Scripted runs (tests) neither read nor write it.
#pragma once
#include <string>
#include <vector>

#include "shotlab/io/run.hpp"
#include "ui/camera.hpp"
#include "ui/layout.hpp"

namespace shotlab {

// Which teaching and aiming aids are drawn.
struct ViewFlags {
  bool trails = true, ghost = true, predicted = true, aim = true;
  bool velocity = false, spin = false, forces = false;
  bool labels = false;        // ball ids beside the balls
  bool centre_of_mass = false;
  bool follow_cue = false;    // the camera follows the cue ball while a shot plays
  bool compare = true;        // the A trails (before a physics change) beside the current ones
  bool help = false;
  int tab = 0;           // of the inspector as last shown: 0 teaching, 1 tuning
  int tab_request = -1;  // a tab to select once (a script, a key), not saved; the user's clicks need none
};

// The side panels: open or collapsed, and their width in unscaled pixels.
struct PanelState {
  bool left_open = true, right_open = true;
  float left_width = 330, right_width = 360;
};

// Events that pause playback when they happen (developers: "stop at the first cushion contact").
struct PauseOn {
  bool ball_ball = false, cushion = false, pocketed = false;
};

struct Settings {
  Camera camera;
  ViewFlags view;
  PanelState panels;
  PauseOn pause_on;
  double slowmo = 1.0;          // simulated seconds per real second
  double impact_speed = 2.0;    // m/s, of the tuning panel's collision probes
  double budget_ms = 10.0;      // physics wall time per frame
  double safety_limit = kRestLimit;  // s of simulated time a shot may run while balls still move
  float ui_scale = 1.0f;        // fonts and widgets; presentation mode uses its own
  bool presentation = false;    // large fonts and thick lines for a projector; not saved: F5 always turns it on
  std::string last_scene;       // path
  std::vector<std::string> recent;  // scene files opened, newest first
  std::string export_dir;       // where plots, tables, strobe pictures and trajectories go; empty: the current folder
};

// The share of the window's width the panels leave to the table (layout.hpp): larger while presenting.
inline float view_share(const Settings& s) { return s.presentation ? kPresentationViewShare : kMinViewShare; }

inline constexpr size_t kRecentFiles = 8;
void remember_file(Settings& s, const std::string& path);  // to the front of `recent`

std::string config_dir();  // created when missing; empty when there is no home
Settings load_settings();  // defaults when absent or unreadable
// Written atomically (files.hpp); returns false with `error` set when it cannot be.
bool save_settings(const Settings& settings, std::string* error = nullptr);

}  // namespace shotlab
