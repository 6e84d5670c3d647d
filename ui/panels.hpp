// The ImGui panels and the 3D overlay: plain functions over the Lab they edit (values are edited in place).
#pragma once
#include <imgui.h>

#include "engine/collision_probe.hpp"
#include "ui/camera.hpp"
#include "ui/lab.hpp"

namespace shotlab {

// A slider over a double, clamped to its range (typed values too: no out-of-range value reaches the engine);
// logarithmic where the range spans decades.
inline bool slider(const char* label, double& v, double lo, double hi, const char* format, bool log = false) {
  return ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &lo, &hi, format,
                             ImGuiSliderFlags_AlwaysClamp | (log ? ImGuiSliderFlags_Logarithmic : 0));
}

// Each side panel returns the edge it leaves free for the 3D view (window pixels).
float play_panel(Lab& lab, Camera& camera);  // panel_play.cpp: scenes, files, playback, aim, edit; its right edge
struct ProbeReadouts;
// The inspector window on the right: a Teaching and a Tuning tab (panel_teach.cpp).
float inspector_panel(Lab& lab, ProbeReadouts& probes);  // its left edge
void teach_panel(Lab& lab);                 // panel_teach.cpp: per-ball readouts, energy, momentum, plots
void help_panel(bool* open);                // panel_play.cpp: shortcuts
void message_banner(Lab& lab);              // panel_play.cpp: errors and notes
// The current shot's trajectory as CSV (engine/io format); throws std::runtime_error. panel_play.cpp.
void export_trajectory(const Lab& lab, const std::string& path);

// The tuning panel's collision probes, re-measured only when their inputs change (panel_tune.cpp).
struct ProbeReadouts {
  ContactMaterial material[3];
  double speed = -1;
  IntegratorOptions integrator;
  CollisionProbe result[3];
  bool valid[3] = {false, false, false};
};
void tune_panel(Lab& lab, ProbeReadouts& probes);

// Trails, predicted paths, aim line and ghost ball, vectors and contact forces, drawn over the 3D view
// (overlay.cpp).
void draw_overlay(const Lab& lab, const Viewport& viewport, ImDrawList* draw);
ImU32 motion_color(Motion m, float alpha = 1.0f);

// Mouse and keyboard on the 3D view (input.cpp).
struct MouseDrag {
  enum Kind { None, Ball, Aim, Orbit, Pan } kind = None;
  int ball = -1;
};
void handle_input(Lab& lab, Camera& camera, const Viewport& viewport, MouseDrag& drag);

}  // namespace shotlab
