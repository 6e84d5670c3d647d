// What persists between runs: $XDG_CONFIG_HOME/shotlab/settings.json (or ~/.config/shotlab). ImGui keeps its
// window layout in imgui.ini beside it. Scripted runs (tests) neither read nor write it.
#pragma once
#include <string>

#include "ui/camera.hpp"

namespace shotlab {

// Which teaching and aiming aids are drawn.
struct ViewFlags {
  bool trails = true, ghost = true, predicted = true, aim = true;
  bool velocity = false, spin = false, forces = false;
  bool inspector = true, help = false;
  int tab = 0;  // of the inspector: 0 teaching, 1 tuning
};

struct Settings {
  Camera camera;
  ViewFlags view;
  double slowmo = 1.0;         // simulated seconds per real second
  double impact_speed = 2.0;   // m/s, of the tuning panel's collision probes
  double budget_ms = 10.0;     // physics wall time per frame
  std::string last_scene;      // path
};

std::string config_dir();  // created when missing; empty when there is no home
Settings load_settings();  // defaults when absent or unreadable
void save_settings(const Settings& settings);

}  // namespace shotlab
