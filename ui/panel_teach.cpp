// The teaching panel: what each ball does (speed, spin, motion state), the system's energy and momentum, and time
// plots of the selected ball, the total energy and the contact force of the last collision.
#include <algorithm>
#include <cmath>

#include "ui/panels.hpp"

namespace shotlab {

namespace {

void plot(const char* label, const std::vector<float>& values, const char* overlay) {
  if (values.empty()) return;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  ImGui::PlotLines(label, values.data(), static_cast<int>(values.size()), 0, overlay, *lo, *hi + 1e-6f * (1 + *hi),
                   ImVec2(0, 70));
}

void ball_table(Lab& lab, const Frame& f) {
  if (!ImGui::BeginTable("balls", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_BordersInnerV,
                         ImVec2(0, 150)))
    return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* h : {"ball", "speed m/s", "spin rad/s", "state"}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  for (int i = 0; i < f.state.ball_count(); ++i) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (ImGui::Selectable(lab.scene.balls[i].spec.id.c_str(), lab.selected == i, ImGuiSelectableFlags_SpanAllColumns))
      lab.selected = i;
    ImGui::TableNextColumn();
    ImGui::Text("%.3f", glm::length(velocity(f.state.x, i)));
    ImGui::TableNextColumn();
    ImGui::Text("%.1f", glm::length(spin(f.state.x, i)));
    ImGui::TableNextColumn();
    const Motion m = i < static_cast<int>(f.motion.size()) ? f.motion[i] : Motion::Stationary;
    ImGui::PushStyleColor(ImGuiCol_Text, motion_color(m));
    ImGui::TextUnformatted(f.state.in_play[i] ? motion_name(m) : "pocketed");
    ImGui::PopStyleColor();
  }
  ImGui::EndTable();
}

}  // namespace

void teach_panel(Lab& lab) {
  const Frame& f = lab.frame();
  ball_table(lab, f);
  const Model& model = lab.shot ? lab.shot->sim().model() : lab.table_model;
  const Energy e = energy(model, f.state);
  const Vec3 p = momentum(model, f.state);
  ImGui::Text("kinetic %.4f J   elastic %.2e J", e.kinetic, e.elastic);
  ImGui::Text("momentum (%.3f, %.3f, %.3f) kg m/s", p.x, p.y, p.z);
  ImGui::Checkbox("velocity", &lab.settings.view.velocity), ImGui::SameLine();
  ImGui::Checkbox("spin", &lab.settings.view.spin), ImGui::SameLine();
  ImGui::Checkbox("contact forces", &lab.settings.view.forces);
  if (!lab.shot || lab.scene.balls.empty()) {
    ImGui::TextDisabled("Plots appear once a shot runs.");
    return;
  }
  // Time plots over the recorded frames up to the time on screen.
  std::vector<float> speed, spin_rate, total;
  const int i = lab.selected;
  for (const Frame& fr : lab.shot->frames()) {
    if (fr.time > lab.view_time) break;
    speed.push_back(static_cast<float>(glm::length(velocity(fr.state.x, i))));
    spin_rate.push_back(static_cast<float>(glm::length(spin(fr.state.x, i))));
    total.push_back(static_cast<float>(fr.energy));
  }
  const std::string id = lab.scene.balls[i].spec.id;
  char text[64];
  std::snprintf(text, sizeof text, "%s: %.3f m/s", id.c_str(), speed.empty() ? 0.0 : speed.back());
  plot("speed", speed, text);
  std::snprintf(text, sizeof text, "%s: %.1f rad/s", id.c_str(), spin_rate.empty() ? 0.0 : spin_rate.back());
  plot("spin", spin_rate, text);
  std::snprintf(text, sizeof text, "total %.4f J", total.empty() ? 0.0 : total.back());
  plot("energy", total, text);
  std::vector<float> force;
  double peak = 0, first = 0, last = 0;
  for (const Sample& s : lab.shot->collision_force())
    if (s.time <= lab.view_time) {
      if (force.empty()) first = s.time;
      force.push_back(static_cast<float>(s.value));
      peak = std::max(peak, s.value);
      last = s.time;
    }
  std::snprintf(text, sizeof text, "peak %.0f N, %.3f ms", peak, (last - first) * 1e3);
  if (force.empty()) ImGui::TextDisabled("no ball-ball collision yet");
  else plot("collision", force, text);
  ImGui::TextDisabled("collision: force at each integrator step");
}



float inspector_panel(Lab& lab, ProbeReadouts& probes) {
  ViewFlags& v = lab.settings.view;
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  if (!v.inspector) return size.x;
  ImGui::SetNextWindowPos(ImVec2(size.x - 350, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(350, size.y), ImGuiCond_FirstUseEver);
  ImGui::Begin("Inspector", &v.inspector);
  // v.tab may be set elsewhere (a script, saved settings): then select that tab once; otherwise follow the clicks.
  static int shown = -1;
  const int wanted = v.tab;
  if (ImGui::BeginTabBar("tabs")) {
    const char* names[2] = {"Teaching", "Tuning"};
    for (int i = 0; i < 2; ++i)
      if (ImGui::BeginTabItem(names[i], nullptr, wanted != shown && wanted == i ? ImGuiTabItemFlags_SetSelected : 0)) {
        if (wanted == shown) v.tab = i;
        shown = i;
        if (i == 0) teach_panel(lab);
        else tune_panel(lab, probes);
        ImGui::EndTabItem();
      }
    ImGui::EndTabBar();
  }
  const float left = ImGui::IsWindowCollapsed() ? size.x : ImGui::GetWindowPos().x;
  ImGui::End();
  return left;
}

}  // namespace shotlab
