// The left panel (for players and coaches, and the teacher's presets): scenes and files, playback, aim, ball
// editing; the help panel; the message banner.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "app/paths.hpp"
#include "engine/io/result_json.hpp"
#include "engine/io/scene_json.hpp"
#include "ui/panels.hpp"

namespace shotlab {

namespace {

struct PresetEntry {
  std::string path, name, description;
};

// The presets directory, read once: a preset's name and its "what to look for" line.
const std::vector<PresetEntry>& presets() {
  static const std::vector<PresetEntry> list = [] {
    std::vector<PresetEntry> out;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(preset_path(""), ec)) {
      if (e.path().extension() != ".json") continue;
      PresetEntry p{e.path().string(), e.path().stem().string(), ""};
      try {
        const Scene s = load_scene(p.path);
        p.name = s.name.empty() ? p.name : s.name;
        p.description = s.description;
      } catch (const std::exception& err) {
        p.description = err.what();
      }
      out.push_back(p);
    }
    std::sort(out.begin(), out.end(), [](const PresetEntry& a, const PresetEntry& b) { return a.path < b.path; });
    return out;
  }();
  return list;
}

// A drawn ball face: click or drag to put the cue tip. Right is the shooter's right, up is follow, down is draw;
// the dashed ring is the miscue limit.
bool tip_widget(CueStrike& cue) {
  const float size = 110, r = size / 2 - 6;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 c{origin.x + size / 2, origin.y + size / 2};
  ImGui::InvisibleButton("tip", ImVec2(size, size));
  ImDrawList* d = ImGui::GetWindowDrawList();
  d->AddCircleFilled(c, r, IM_COL32(240, 238, 225, 255), 48);
  for (int k = 0; k < 24; k += 2) {
    const float a0 = k * 2 * float(M_PI) / 24, a1 = (k + 1) * 2 * float(M_PI) / 24;
    const float m = r * static_cast<float>(cue.miscue_limit);
    d->AddLine({c.x + m * std::cos(a0), c.y + m * std::sin(a0)}, {c.x + m * std::cos(a1), c.y + m * std::sin(a1)},
               IM_COL32(200, 60, 60, 255), 1.5f);
  }
  d->AddLine({c.x - r, c.y}, {c.x + r, c.y}, IM_COL32(150, 150, 150, 255));
  d->AddLine({c.x, c.y - r}, {c.x, c.y + r}, IM_COL32(150, 150, 150, 255));
  const ImVec2 tip{c.x + r * float(cue.side), c.y - r * float(cue.height)};
  d->AddCircleFilled(tip, 6, IM_COL32(40, 90, 220, 255));
  if (!ImGui::IsItemActive()) return false;
  const ImVec2 m = ImGui::GetIO().MousePos;
  double side = (m.x - c.x) / r, height = -(m.y - c.y) / r;
  const double len = std::hypot(side, height);
  if (len > 0.9) side *= 0.9 / len, height *= 0.9 / len;  // keep the tip on the ball
  cue.side = side;
  cue.height = height;
  return true;
}

void scenes_section(Lab& lab) {
  for (const PresetEntry& p : presets()) {
    if (ImGui::Selectable(p.name.c_str(), lab.scene_path == p.path)) lab.load(p.path);
    if (ImGui::IsItemHovered() && !p.description.empty()) ImGui::SetTooltip("%s", p.description.c_str());
  }
  static std::string path;  // the text being typed, not program state
  ImGui::InputText("##path", &path);
  ImGui::SameLine();
  if (ImGui::Button("Load")) lab.load(path);
  ImGui::SameLine();
  if (ImGui::Button("Save")) {
    const std::string to = path.empty() ? lab.scene_path : path;
    try {
      save_scene(to, lab.scene);
      lab.note = "saved " + to;
    } catch (const std::exception& e) {
      lab.error = e.what();
    }
  }
  if (ImGui::Button("Screenshot (F12)")) lab.screenshot_request = "shotlab-screenshot.png";
  ImGui::SameLine();
  if (ImGui::Button("Export CSV") && lab.shot) {
    try {
      export_trajectory(lab, "shotlab-trajectory.csv");
      lab.note = "wrote shotlab-trajectory.csv";
    } catch (const std::exception& e) {
      lab.error = e.what();
    }
  }
}

void playback_section(Lab& lab) {
  if (ImGui::Button(lab.shot ? (lab.playing ? "Pause" : "Play") : "Shoot")) {
    if (lab.shot) lab.playing = !lab.playing;
    else lab.shoot();
  }
  ImGui::SameLine();
  if (ImGui::Button("Step")) lab.step();
  ImGui::SameLine();
  if (ImGui::Button("Replay")) lab.replay();
  ImGui::SameLine();
  if (ImGui::Button("Undo")) lab.undo();
  ImGui::SameLine();
  if (ImGui::Button("Next")) lab.continue_from_rest();
  slider("speed##clock", lab.settings.slowmo, 1e-3, 4.0, "%.3gx real time", true);
  if (lab.shot) {
    double t = lab.view_time;
    if (slider("time##scrub", t, 0.0, std::max(lab.shot->sim().time(), 1e-9), "%.4f s")) {
      lab.playing = false;
      lab.view_time = t;
    }
    ImGui::Text("t = %.4f s%s", lab.view_time, lab.shot->finished() ? "  (shot over)" : "");
    if (lab.playing && lab.achieved_speed < 0.95)
      ImGui::TextColored(ImVec4(1, 0.7f, 0.2f, 1), "physics behind: clock slowed to %.0f%% of the set speed",
                         100 * lab.achieved_speed);
  } else {
    ImGui::TextDisabled("aiming: S or Space shoots");
  }
}

void aim_section(Lab& lab) {
  if (lab.scene.balls.empty()) return;
  bool has_cue = lab.scene.cue.has_value();
  if (ImGui::Checkbox("cue strike", &has_cue)) {
    if (has_cue) lab.scene.cue = CueStrike{lab.scene.balls[lab.selected].spec.id};
    else lab.scene.cue.reset();
    lab.scene_changed();
  }
  if (!lab.scene.cue) return;
  CueStrike& cue = *lab.scene.cue;
  bool changed = false;
  ImGui::Text("cue ball: %s", cue.ball.c_str());
  changed |= slider("speed m/s", cue.speed, 0.05, 15.0, "%.2f");
  double aim = cue.aim * 180 / M_PI, elevation = cue.elevation * 180 / M_PI;
  if (ImGui::DragScalar("aim deg", ImGuiDataType_Double, &aim, 0.01f, nullptr, nullptr, "%.2f")) {
    cue.aim = aim * M_PI / 180;
    changed = true;
  }
  if (slider("elevation deg", elevation, 0.0, 85.0, "%.1f")) {
    cue.elevation = elevation * M_PI / 180;
    changed = true;
  }
  changed |= tip_widget(cue);
  ImGui::SameLine();
  ImGui::Text("side %+.2f R\n%s %.2f R%s", cue.side, cue.height >= 0 ? "follow" : "draw", std::abs(cue.height),
              std::hypot(cue.side, cue.height) > cue.miscue_limit ? "\nMISCUE risk" : "");
  if (changed) lab.scene_changed();
}

}  // namespace

void export_trajectory(const Lab& lab, const std::string& path) {
  // Re-simulates the shot from its start, a row set every 1/240 s up to the time reached (the result does not
  // depend on how time is sliced, so it is the shot that was watched).
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  write_trajectory_header(out);
  Prepared p = prepare(lab.shot->start());
  Simulation sim(std::move(p.model), std::move(p.state));
  write_trajectory_rows(out, sim);
  while (sim.time() < lab.shot->sim().time() - 1e-12 && sim.status() == Status::Ok) {
    sim.advance(std::min(1.0 / 240, lab.shot->sim().time() - sim.time()));
    write_trajectory_rows(out, sim);
  }
}

float play_panel(Lab& lab, Camera& camera) {
  ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(320, ImGui::GetIO().DisplaySize.y), ImGuiCond_FirstUseEver);
  ImGui::Begin("Shot lab");
  ImGui::TextWrapped("%s", lab.scene.name.c_str());
  if (!lab.scene.description.empty()) {
    ImGui::TextColored(ImVec4(0.7f, 0.9f, 1, 1), "What to look for:");
    ImGui::TextWrapped("%s", lab.scene.description.c_str());
  }
  if (ImGui::CollapsingHeader("Scenes and files")) scenes_section(lab);
  if (ImGui::CollapsingHeader("Playback", ImGuiTreeNodeFlags_DefaultOpen)) playback_section(lab);
  if (ImGui::CollapsingHeader("Aim", ImGuiTreeNodeFlags_DefaultOpen)) aim_section(lab);
  if (ImGui::CollapsingHeader("View")) {
    ViewFlags& v = lab.settings.view;
    ImGui::Checkbox("trails", &v.trails), ImGui::SameLine(), ImGui::Checkbox("ghost", &v.ghost), ImGui::SameLine(),
        ImGui::Checkbox("predicted", &v.predicted);
    ImGui::Checkbox("aim line", &v.aim), ImGui::SameLine(), ImGui::Checkbox("velocity", &v.velocity), ImGui::SameLine(),
        ImGui::Checkbox("spin", &v.spin);
    ImGui::Checkbox("contact forces", &v.forces);
    ImGui::SameLine(), ImGui::Checkbox("inspector", &v.inspector);
    if (ImGui::Button("Top view (T)")) camera.top_view();
    ImGui::SameLine();
    if (ImGui::Button("Reset view")) camera.reset();
    ImGui::SameLine();
    if (ImGui::Button("Help (H)")) v.help = true;
  }
  if (ImGui::CollapsingHeader("Balls")) {
    ImGui::TextWrapped("Drag a ball to move it, shift+click the cloth to add one, Del removes the selected ball.");
    if (ImGui::Button("Rack 15 balls")) lab.rack();
    ImGui::SameLine();
    if (ImGui::Button("Remove selected")) lab.remove_ball(lab.selected);
    ImGui::Checkbox("allow overlaps", &lab.scene.allow_overlap);
  }
  const float right = ImGui::IsWindowCollapsed() ? 0.0f : ImGui::GetWindowPos().x + ImGui::GetWindowWidth();
  ImGui::End();
  return right;
}

void help_panel(bool* open) {
  if (!*open) return;
  ImGui::SetNextWindowPos(ImVec2(400, 120), ImGuiCond_FirstUseEver);
  ImGui::Begin("Help", open, ImGuiWindowFlags_AlwaysAutoResize);
  static const char* rows[][2] = {
      {"Left click cloth / drag", "aim the cue there"}, {"Left drag a ball", "move it (before the shot)"},
      {"Shift + left click", "add a ball"}, {"Del", "remove the selected ball"},
      {"Right drag / shift+right, middle", "orbit / pan the camera"}, {"Wheel", "zoom"},
      {"T / Home", "top view / reset view"}, {"Left, Right (shift, ctrl)", "fine aim 0.1 deg (1, 0.01)"},
      {"Up, Down", "cue speed +-0.1 m/s"}, {"S or Enter", "shoot"}, {"Space", "play / pause (shoot when aiming)"},
      {".", "single step (one frame of simulated time)"}, {"[ ]", "slower / faster clock (1/1000 to 4x)"},
      {"R", "replay the shot"}, {"U or Ctrl+Z", "undo: back to the position and aim before the shot"},
      {"N", "next shot from where the balls stopped"}, {"V / F", "velocity and spin vectors / contact forces"},
      {"F12", "screenshot (shotlab-screenshot.png)"}, {"H or F1", "this help"}};
  if (ImGui::BeginTable("keys", 2)) {
    for (const auto& r : rows) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r[0]);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(r[1]);
    }
    ImGui::EndTable();
  }
  ImGui::TextWrapped("Trail colours: orange sliding, blue rolling, magenta airborne, yellow spinning in place.");
  ImGui::End();
}

void message_banner(Lab& lab) {
  if (lab.error.empty() && lab.note.empty()) return;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(size.x / 2, 8), ImGuiCond_Always, ImVec2(0.5f, 0));
  ImGui::SetNextWindowSizeConstraints(ImVec2(200, 0), ImVec2(size.x * 0.55f, 300));
  ImGui::Begin("##message", nullptr, ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing);
  if (!lab.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.45f, 0.4f, 1));
    ImGui::TextWrapped("%s", lab.error.c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("Dismiss")) lab.error.clear();
    if (!lab.history.empty()) {
      ImGui::SameLine();
      if (ImGui::Button("Undo")) lab.undo();
    }
  } else {
    ImGui::TextUnformatted(lab.note.c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("x")) lab.note.clear();
  }
  ImGui::End();
}

}  // namespace shotlab
