// Practice (players and coaches): a position target and the miss, kept shots to compare, a camera that follows the
// cue ball. View: which aids are drawn, the camera, UI scale and presentation mode, pictures.
#include <imgui.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "ui/framing.hpp"
#include "ui/panels.hpp"
#include "ui/pictures.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

ImU32 kept_colour(int k, float alpha) {
  static const ImU32 colours[] = {IM_COL32(255, 120, 120, 255), IM_COL32(120, 255, 140, 255),
                                  IM_COL32(140, 160, 255, 255), IM_COL32(255, 220, 100, 255),
                                  IM_COL32(230, 130, 255, 255), IM_COL32(100, 240, 240, 255)};
  const ImU32 c = colours[k % 6];
  return (c & 0x00FFFFFF) | (static_cast<ImU32>(alpha * 255) << 24);
}

void practice_section(Lab& lab) {
  text_wrapped("Target: pick the Target tool (Aim section) and click where the cue ball should stop.");
  if (lab.target) {
    const Fields f({"radius"});
    f.label("radius");
    slider("##target radius", lab.target_radius, 0.01, 0.3, "%.2f m");
    if (const auto miss = lab.target_miss())
      coloured_wrapped(*miss <= lab.target_radius ? ImVec4(0.5f, 1, 0.5f, 1) : ImVec4(1, 0.7f, 0.3f, 1),
                         "%s: %.1f cm from the target%s", lab.shot ? "the cue ball stopped" : "predicted",
                         *miss * 100, *miss <= lab.target_radius ? " (inside)" : "");
    if (ImGui::SmallButton("clear target")) lab.clear_target();
  }
  ImGui::Separator();
  if (ImGui::Button("Keep this shot (K)")) lab.keep_shot();
  mark("Keep shot");
  same_line_if_fits("Clear kept");
  ImGui::BeginDisabled(lab.kept.empty());
  if (ImGui::Button("Clear kept")) lab.clear_kept();
  mark("Clear kept");
  ImGui::EndDisabled();
  for (size_t k = 0; k < lab.kept.size(); ++k) {
    ImGui::PushID(static_cast<int>(k));
    ImGui::Checkbox("##visible", &lab.kept[k].visible);
    ImGui::SameLine();
    // Wrapped, not cut at the panel's edge: two attempts differ at the end of the label (the aim).
    coloured_wrapped(ImGui::ColorConvertU32ToFloat4(kept_colour(lab.kept[k].colour)), "%s", lab.kept[k].label.c_str());
    ImGui::PopID();
  }
  fitting_checkbox("camera follows the cue ball", "follow cue ball", &lab.settings.view.follow_cue);
}

void view_section(Lab& lab, Camera& camera) {
  ViewFlags& v = lab.settings.view;
  // Each on the row before when it fits: at a large UI scale they wrap instead of running out of the panel.
  ImGui::Checkbox("trails", &v.trails), same_line_if_checkbox_fits("ghost");
  ImGui::Checkbox("ghost", &v.ghost), same_line_if_checkbox_fits("predicted");
  ImGui::Checkbox("predicted", &v.predicted);
  ImGui::Checkbox("aim line", &v.aim), same_line_if_checkbox_fits("velocity");
  ImGui::Checkbox("velocity", &v.velocity), same_line_if_checkbox_fits("spin");
  ImGui::Checkbox("spin", &v.spin);
  ImGui::Checkbox("contact forces", &v.forces), same_line_if_checkbox_fits("labels");
  ImGui::Checkbox("labels", &v.labels);
  ImGui::Checkbox("centre of mass", &v.centre_of_mass), same_line_if_checkbox_fits("A/B compare");
  ImGui::Checkbox("A/B compare", &v.compare);
  if (ImGui::Button("Top view (T)")) camera.top_view();
  same_line_if_fits("Fit table (Home)");
  if (ImGui::Button("Fit table (Home)")) home_view(camera, lab.scene);
  same_line_if_fits("Help (H)");
  if (ImGui::Button("Help (H)")) v.help = true;
  // A list of steps rather than a slider: one stray click on a slider set 1.61x, and the panels' rows ran out of them.
  const Fields f({"UI scale"});
  f.label("UI scale");
  char shown[16];
  std::snprintf(shown, sizeof shown, "%.2fx", lab.settings.ui_scale);
  if (ImGui::BeginCombo("##scale", shown)) {
    for (const float step : {0.75f, 1.0f, 1.25f, 1.5f, 1.75f, 2.0f, 2.5f, 3.0f}) {
      char text[16];
      std::snprintf(text, sizeof text, "%.2fx", step);
      if (ImGui::Selectable(text, step == lab.settings.ui_scale)) lab.settings.ui_scale = step;
    }
    ImGui::EndCombo();
  }
  mark("UI scale");
  fitting_checkbox("presentation mode (F5)", "presentation", &lab.settings.presentation);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("large fonts for a projector");
  if (ImGui::Button("Screenshot (F12)")) lab.screenshot_request = export_path(lab, "screenshot", "png");
  same_line_if_fits("Strobe picture");
  ImGui::BeginDisabled(!lab.shot);
  if (ImGui::Button("Strobe picture")) lab.strobe_request = export_path(lab, "strobe", "png");
  mark("Strobe picture");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("the shot as a multiple exposure, as a PNG: the balls at %d moments from its start to its end, "
                      "the earliest faintest", kStrobeExposures);
  same_line_if_fits("Export CSV");
  if (ImGui::Button("Export CSV")) try {
      const std::string path = export_path(lab, "trajectory", "csv");
      export_trajectory(lab, path);
      lab.say(MessageKind::Note, "wrote " + path);
    } catch (const std::exception& e) {
      lab.say(MessageKind::Refused, e.what());
    }
  ImGui::EndDisabled();
  ImGui::TextUnformatted("export folder");
  ImGui::SetNextItemWidth(-1);
  static char dir[512];
  snprintf(dir, sizeof dir, "%s", lab.settings.export_dir.c_str());
  // Empty: the folder the program was started in, named in full so that a teacher knows where the files go.
  static const std::string here = [] {
    std::error_code ec;
    const std::string cwd = std::filesystem::current_path(ec).string();
    return "(" + (cwd.empty() ? std::string("the current folder") : cwd) + ")";
  }();
  if (ImGui::InputTextWithHint("##exportdir", here.c_str(), dir, sizeof dir)) lab.settings.export_dir = dir;
}

}  // namespace shotlab
