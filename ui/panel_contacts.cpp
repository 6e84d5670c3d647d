// The per-contact inspector (developers): every contact of the shot other than the bed's (the pair, when it began,
// how long it lasted, its peak force and depth); the selected one's force and penetration over time.
#include <imgui.h>

#include <algorithm>

#include "ui/panels.hpp"
#include "ui/ticks.hpp"
#include "ui/widgets.hpp"

namespace shotlab {

namespace {

int contacts_table(const ContactLog& log, int selected) {
  const float rows = std::min<float>(log.contacts.size(), 8) + 1.5f;
  // Each column as wide as its widest cell and the table scrolled across in a narrow panel: cut names and headers
  // ("1 - pocket-right-frc", "begins...") told two rows apart by nothing.
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY | ImGuiTableFlags_ScrollX |
                                ImGuiTableFlags_SizingFixedFit;
  const float scrollbar = ImGui::GetStyle().ScrollbarSize;
  if (!ImGui::BeginTable("contacts", 5, flags, ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * rows + scrollbar)))
    return selected;
  ImGui::TableSetupScrollFreeze(0, 1);
  const std::string depth = std::string("depth (") + kMicro + "m)";
  for (const char* h : {"pair", "begins (s)", "lasts (ms)", "peak (N)", depth.c_str()}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  for (int k = 0; k < static_cast<int>(log.contacts.size()); ++k) {
    const ContactTrace& c = log.contacts[k];
    const double end = c.end >= 0 ? c.end : log.until;
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::PushID(k);
    if (ImGui::Selectable(c.label().c_str(), k == selected, ImGuiSelectableFlags_SpanAllColumns)) selected = k;
    ImGui::PopID();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(format_time(c.begin, true).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.3f%s", (end - c.begin) * 1e3, c.end < 0 ? "+" : "");
    ImGui::TableNextColumn();
    ImGui::Text("%.0f", c.peak_force());
    ImGui::TableNextColumn();
    ImGui::Text("%.1f", c.max_depth() * 1e6);
  }
  pass_wheel_on();
  ImGui::EndTable();
  return selected;
}

}  // namespace

void contacts_section(Lab& lab) {
  if (!lab.shot) return hint("Shoot to list the shot's contacts.");
  const ContactLog* log = lab.contact_log();
  if (!log) return ImGui::TextDisabled("tracing the contacts...");
  if (log->contacts.empty()) return hint("no contact besides the bed's so far");
  static int selected = 0;
  selected = std::clamp(contacts_table(*log, selected), 0, static_cast<int>(log->contacts.size()) - 1);
  const ContactTrace& c = log->contacts[selected];
  const double end = std::max(c.end >= 0 ? c.end : log->until, c.begin + 1e-6);
  std::vector<double> depth_um;
  for (double d : c.depth) depth_um.push_back(d * 1e6);
  PlotSpec force{"normal force, " + c.label(), "N", lab.view_time, c.begin, end};
  PlotSpec depth{"penetration, " + c.label(), std::string(kMicro) + "m", lab.view_time, c.begin, end};
  for (PlotSpec* spec : {&force, &depth}) spec->origin = c.begin, spec->origin_name = "contact start";
  if (const auto t = lab_plot(lab, "contact_force", force, {{"force", IM_COL32(255, 110, 90, 255), c.time, c.force}}, em(120)))
    lab.seek(*t);
  if (const auto t = lab_plot(lab, "contact_depth", depth, {{"depth", IM_COL32(120, 230, 120, 255), c.time, depth_um}}, em(120)))
    lab.seek(*t);
  if (ImGui::SmallButton("go to its start")) lab.seek(c.begin);
}

}  // namespace shotlab
