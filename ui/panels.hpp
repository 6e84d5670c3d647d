// The ImGui panels: plain functions over the Lab they edit (values are edited in place). The left panel (players
// and coaches: scenes, playback, aim, practice) and the right one (the inspector: Teaching and Tuning tabs) sit at
// the window's edges where layout.hpp puts them.
#pragma once
#include <imgui.h>

#include <future>
#include <string>

#include "shotlab/collision_probe.hpp"
#include "ui/camera.hpp"
#include "ui/lab.hpp"
#include "ui/layout.hpp"
#include "ui/plot.hpp"

namespace shotlab {

// The tuning panel's collision probes and the elasticity control's solver, run on a worker thread whenever their
// inputs change: a probe at an absurd stiffness can take a while and must not stall the window.
// The material pairs the Tuning tab edits: ball_ball, ball_cloth, ball_cushion and, on a table with pockets,
// ball_pocket (panel_tune.cpp names them).
inline constexpr int kTunedPairs = 4;
struct ProbeReadouts {
  ContactMaterial material[kTunedPairs];
  double speed = -1;
  IntegratorOptions integrator;
  CollisionProbe result[kTunedPairs];
  bool valid[kTunedPairs] = {};
};
struct Tuning {
  ProbeReadouts probes;
  std::future<ProbeReadouts> probe_job;
  double restitution[kTunedPairs] = {-1, -1, -1, -1};  // the elasticity control's wanted e per pair, < 0: not set
  std::future<std::pair<int, double>> damping_job;  // pair index and the damping that gives the wanted e
  bool busy() const;
};

// Each returns the panel's collapsed state as the user left it (true: open).
// Each where `layout` puts it; a drag of its inner edge sets its width in the settings (widgets.hpp).
bool left_panel(Lab& lab, Camera& camera, const Layout& layout);    // panel_play.cpp
bool inspector_panel(Lab& lab, Tuning& tuning, const Layout& layout);  // panel_teach.cpp

void scene_section(Lab& lab);         // panel_files.cpp: presets, recent files, open, save
void practice_section(Lab& lab);      // panel_practice.cpp: position target, kept shots, camera follow
void margin_section(Lab& lab);        // panel_margin.cpp: success under stroke noise, sensitivity, aim x speed map
void view_section(Lab& lab, Camera& camera);  // panel_practice.cpp: drawing aids, UI scale, pictures
void teach_panel(Lab& lab);           // panel_teach.cpp
void teach_plots(Lab& lab);           // panel_plots.cpp
void tune_panel(Lab& lab, Tuning& tuning);  // panel_tune.cpp
void contacts_section(Lab& lab);      // panel_contacts.cpp: every contact of the shot, its force history
void measured_section(Lab& lab);      // panel_measured.cpp: a measured shot and the fit of its strike
void help_panel(bool* open, float top);  // panel_play.cpp: shortcuts, below y = top (px: the banner's bottom)
// panel_play.cpp: errors and notes over the 3D view; returns the banner's bottom (px), 0 when none is shown.
float message_banner(Lab& lab, const Rect& view);
// The frame's timing in the view's corner: frame time and rate, physics time this frame (developers).
void status_line(const Lab& lab, const Rect& view, double frame_seconds, bool slept);

// A plot with its exports handled (files named after the scene, in the export folder); returns the picked time.
std::optional<double> lab_plot(Lab& lab, const char* id, PlotSpec spec, const std::vector<PlotSeries>& series,
                               float height);
// Where an export goes: a new file in the export folder, named after the scene and `what`.
std::string export_path(const Lab& lab, const std::string& what, const std::string& ext);
// The current shot's trajectory as CSV (engine/io format); throws std::runtime_error. panel_files.cpp.
void export_trajectory(const Lab& lab, const std::string& path);

// Trails, predicted paths, aim line and ghost ball, vectors and contact forces, targets, labels, drawn over the 3D
// view (overlay.cpp).
void draw_overlay(const Lab& lab, const Viewport& viewport, ImDrawList* draw);
ImU32 motion_color(Motion m, float alpha = 1.0f);
ImU32 kept_colour(int k, float alpha = 1.0f);

// Mouse and keyboard on the 3D view (input.cpp).
struct MouseDrag {
  enum Kind { None, Ball, Aim, FineAim, Orbit, Pan, Target } kind = None;
  int ball = -1;
  double aim0 = 0;     // rad, the aim when a fine-aim drag began
  float x0 = 0;        // pixels, where it began
};
void handle_input(Lab& lab, Camera& camera, const Viewport& viewport, MouseDrag& drag, bool over_view);

}  // namespace shotlab
